#include "comparisons/engines/segment_plane_engines.h"

namespace tecido {

const std::vector<SegmentPlaneEngine>& segment_plane_engines() {
  static const std::vector<SegmentPlaneEngine> engines = {
      {"core", [](const BoundedPlane& p, const Vec3& a, const Vec3& b) { return std::optional(segment_plane(p, a, b)); }},
  };
  return engines;
}

const SegmentPlaneEngine* find_segment_plane_engine(const std::string& name) {
  for (const auto& e : segment_plane_engines())
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace tecido
