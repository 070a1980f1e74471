#include "comparisons/suites/tradeoff/curtain.h"

#include "comparisons/suites/random.h"
#include "core/scene/cloth_builder.h"

namespace tecido::suites::tradeoff {

Scene hanging_cloth(int n) {
  Scene s;
  ClothGridSpec g = unit_square_cloth(n);
  g.axis_u = Vec3::UnitX();
  g.axis_v = -Vec3::UnitZ();  // rows go down: row 0 is the top edge
  g.total_mass = 0.1;
  g.stiffness_a = 0.5;
  g.pins = {{0, 0}, {0, n - 1}};
  append_cloth(s, g);
  s.forces.gravity = Vec3(0, 0, -9.81);
  return s;
}

Scene nudged(const Scene& scene, std::uint64_t seed, bool out_of_plane, double size) {
  Scene p = scene;
  Rng r(seed);
  for (std::size_t i = 0; i < p.particles.size(); ++i) {
    if (p.particles.pinned[i]) continue;
    Vec3 d = r.unit_vector();
    if (out_of_plane) {
      d = Vec3(0, d.y() >= 0.0 ? 1.0 : -1.0, 0);
    } else {
      d.y() = 0.0;
      d = d.norm() > 0.0 ? Vec3(d / d.norm()) : Vec3::UnitX();
    }
    p.particles.x[i] += size * d;
  }
  return p;
}

}  // namespace tecido::suites::tradeoff
