#include "comparisons/suites/obstacles/block_scene.h"

#include "core/cloth/cloth_builder.h"

namespace tecido::suites::obstacles {

Scene block_scene(const Settings& s, int n, bool edge_contacts) {
  Scene sc;
  sc.dt = s.block_dt;
  sc.forces.gravity = Vec3(0, 0, -s.g);
  ClothGridSpec g;
  g.rows = g.cols = n;
  g.spacing = s.cloth_side / (n - 1);
  g.origin = Vec3(-0.5 * s.cloth_side, -0.5 * s.cloth_side, s.cloth_height);
  g.total_mass = s.cloth_mass;
  g.stiffness_b = s.cloth_ks;
  g.damping = s.cloth_damping;
  g.elasticity = s.cloth_elasticity;
  append_cloth(sc, g);
  Obstacle block;
  block.kind = ObstacleKind::Box;
  block.center = Vec3(0, 0, -s.block_half);
  block.half_extents = Vec3::Constant(s.block_half);
  block.friction = s.block_friction;
  sc.obstacles.push_back(block);
  sc.edge_contacts = edge_contacts;
  return sc;
}

Scene sphere_scene(const Settings& s, int n) {
  Scene sc = block_scene(s, n, false);
  Obstacle& o = sc.obstacles.front();
  o = Obstacle{};
  o.kind = ObstacleKind::Sphere;
  o.center = Vec3(0, 0, -s.sphere_radius);
  o.radius = s.sphere_radius;
  o.friction = s.block_friction;
  return sc;
}

OrientedBox block_of(const Scene& scene) {
  const Obstacle& o = scene.obstacles.front();
  return OrientedBox{o.center, o.orientation, o.half_extents};
}

std::vector<std::array<int, 2>> stiff_springs(const Scene& scene) {
  std::vector<std::array<int, 2>> out;
  for (const Spring& sp : scene.forces.springs)
    if (sp.stiffness > 0.0) out.push_back({sp.i, sp.j});
  return out;
}

}  // namespace tecido::suites::obstacles
