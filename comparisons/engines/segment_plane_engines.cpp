#include "comparisons/engines/segment_plane_engines.h"

#include "core/geometry/segment_plane_seed.h"

#include "reference/exact_referee.h"
#include "reference/fcl_adapter.h"

namespace tecido {

const std::vector<SegmentPlaneEngine>& segment_plane_engines() {
  static const std::vector<SegmentPlaneEngine> engines = {
      {"core", [](const BoundedPlane& p, const Vec3& a, const Vec3& b) { return std::optional(segment_plane(p, a, b)); }},
      {"core-seed",
       [](const BoundedPlane& p, const Vec3& a, const Vec3& b) { return std::optional(segment_plane_seed(p, a, b)); }},
      {"fcl", &reference::fcl_segment_plane},
      {"exact",
       [](const BoundedPlane& p, const Vec3& a, const Vec3& b) {
         const reference::ExactSegmentPlane e = reference::exact_segment_plane(p, a, b);
         return std::optional(SegmentPlaneHit{e.hit, e.t});
       }},
  };
  return engines;
}

const SegmentPlaneEngine* find_segment_plane_engine(const std::string& name) {
  for (const auto& e : segment_plane_engines())
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace tecido
