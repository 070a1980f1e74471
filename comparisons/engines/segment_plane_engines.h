#pragma once
/// Segment-versus-bounded-plane engines, by name: a name and a function. Adding an engine is
/// one adapter and one line in segment_plane_engines.cpp; every command and suite picks it up.
#include "core/geometry/segment_plane.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace tecido {

struct SegmentPlaneEngine {
  std::string name;
  /// nullopt: the engine could not answer this case (printed as null).
  std::function<std::optional<SegmentPlaneHit>(const BoundedPlane&, const Vec3&, const Vec3&)> test;
};

/// Every registered engine, in a fixed order ("core" first).
const std::vector<SegmentPlaneEngine>& segment_plane_engines();
/// The engine with that name, or nullptr.
const SegmentPlaneEngine* find_segment_plane_engine(const std::string& name);

}  // namespace tecido
