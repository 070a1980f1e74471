#pragma once
/// The query engines of one run: the built-in registries (tri_tri_engines.h,
/// segment_plane_engines.h), unchanged, followed by the outside engines named on the command line
/// that answer the same question (outside/outside_engines.h). Commands and suites ask here by name
/// and get every answer of a batch at once: a built-in engine loops over the batch, an outside
/// engine gets the whole batch through its door (a process answers it in few round trips).
#include "comparisons/engines/outside/outside_engines.h"
#include "core/geometry/segment_plane.h"

#include <optional>
#include <string>
#include <vector>

namespace tecido {

/// Built-in tri-tri engines, then the outside engines answering tri_tri (`outside` may be null).
std::vector<std::string> tri_tri_engine_names(const outside::OutsideEngines* outside);
/// Engine `name`'s answers to `queries`, in order (std::invalid_argument for an unknown name).
std::vector<std::optional<bool>> tri_tri_answers(const std::string& name, const std::vector<outside::TriTriQuery>& queries,
                                                 const outside::OutsideEngines* outside);

/// Built-in segment-plane engines, then the outside engines answering plane.
std::vector<std::string> segment_plane_engine_names(const outside::OutsideEngines* outside);
std::vector<std::optional<SegmentPlaneHit>> segment_plane_answers(const std::string& name,
                                                                  const std::vector<outside::SegmentPlaneQuery>& queries,
                                                                  const outside::OutsideEngines* outside);

/// Whether an outside engine answers continuous collision queries of some kind.
bool answers_ccd(const outside::OutsideEngine& engine);
/// Built-in ccd engines (ccd_engines.h), then the outside engines answering ccd of some kind.
std::vector<std::string> ccd_engine_names(const outside::OutsideEngines* outside);
/// Engine `name`'s answers to `queries` (doubles), in order: a built-in engine query by query
/// (answer_ccd_entry), an outside one in one batch (std::invalid_argument for an unknown name).
std::vector<std::optional<CcdAnswer>> ccd_answers(const std::string& name, const std::vector<CcdQuery>& queries,
                                                  const outside::OutsideEngines* outside);
/// The outside engines answering ccd, in load order (`outside` may be null).
std::vector<outside::OutsideEnginePtr> outside_ccd_engines(const outside::OutsideEngines* outside);

/// Every built-in engine's name (tri-tri, segment-plane, self-collision, core's integrators): an
/// outside engine may not take one.
std::vector<std::string> builtin_engine_names();

}  // namespace tecido
