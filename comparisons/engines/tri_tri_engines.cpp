#include "comparisons/engines/tri_tri_engines.h"

#include "core/geometry/tri_tri_intersect.h"
#include "core/geometry/tri_tri_moller_trumbore.h"
#include "core/geometry/tri_tri_rotation.h"
#include "reference/ccd_adapter.h"
#include "reference/exact_referee.h"
#include "reference/fcl_adapter.h"

namespace tecido {

namespace {
template <bool (*F)(const Triangle&, const Triangle&)>
std::optional<bool> wrap(const Triangle& a, const Triangle& b) {
  return F(a, b);
}
}  // namespace

const std::vector<TriTriEngine>& tri_tri_engines() {
  static const std::vector<TriTriEngine> engines = {
      {"core", &wrap<&tri_tri_intersect>},
      {"core-rotation", &wrap<&tri_tri_rotation>},
      {"core-mt", &wrap<&tri_tri_moller_trumbore>},
      {"fcl", &wrap<&reference::fcl_tri_tri>},
      {"ccd-gjk", &reference::ccd_gjk_tri_tri},
      {"ccd-mpr", &reference::ccd_mpr_tri_tri},
      {"exact", &wrap<&reference::exact_tri_tri>},
  };
  return engines;
}

const TriTriEngine* find_tri_tri_engine(const std::string& name) {
  for (const auto& e : tri_tri_engines())
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace tecido
