#pragma once
/// Triangle-triangle engines, by name: a name and a function of two triangles. Adding an
/// engine is one adapter and one line in tri_tri_engines.cpp; `tecido tritri` and the tritri
/// suite pick it up. Closed triangles: touching counts as intersecting.
#include "core/geometry/types.h"

#include <optional>
#include <string>
#include <vector>

namespace tecido {

struct TriTriEngine {
  std::string name;
  /// nullopt: the engine could not answer (printed as null). A plain function pointer, so the
  /// benchmark loops measure the test, not a std::function call.
  std::optional<bool> (*test)(const Triangle&, const Triangle&);
};

/// Every registered engine in a fixed order: core, core-rotation, core-mt, then the references
/// (fcl, ccd-gjk, ccd-mpr, exact) when they are built.
const std::vector<TriTriEngine>& tri_tri_engines();
const TriTriEngine* find_tri_tri_engine(const std::string& name);

}  // namespace tecido
