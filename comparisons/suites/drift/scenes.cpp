#include "comparisons/suites/drift/scenes.h"

#include "comparisons/suites/random.h"
#include "core/scene/cloth_builder.h"

namespace tecido::suites::drift {

namespace {

Conservative two_body() {
  Conservative c{"two-body-3d",
                 "two free particles (1 kg, 2 kg) on a spring (ks = 9 N/m, l = 1 m), stretched and spinning, dt = 1e-3 s",
                 {}};
  c.scene.particles.add(Vec3(0, 0, 0), Vec3(0.2, -0.6, 0.1), 1.0, 1.0, false);
  c.scene.particles.add(Vec3(1.3, 0.1, 0), Vec3(-0.1, 0.3, 0.05), 2.0, 1.0, false);
  c.scene.forces.springs.push_back(Spring{0, 1, 9.0, 1.0, 0.0});
  c.scene.dt = 1e-3;
  return c;
}

Conservative free_cloth(std::uint64_t seed) {
  Conservative c{"free-cloth",
                 "an unpinned 8x8 cloth (ks_B = 1 N/m, ks_A = 0.5 N/m, 0.5 kg) with random initial velocities, no "
                 "gravity, dt = 2e-4 s: only internal forces",
                 {}};
  ClothGridSpec g;
  g.rows = g.cols = 8;
  g.spacing = 0.1;
  g.total_mass = 0.5;
  g.stiffness_b = 1.0;
  g.stiffness_a = 0.5;
  append_cloth(c.scene, g);
  Rng r(substream(seed, 42));
  for (auto& v : c.scene.particles.v) v = 0.05 * r.in_box(-1, 1);
  c.scene.dt = 2e-4;  // omega_max h ~ 0.006: explicit Euler grows visibly but stays finite over 10^5 steps
  return c;
}

Scene grid_cloth(int n, double spacing, double mass, double ks, const Vec3& origin, const Vec3& v_axis,
                 std::vector<std::array<int, 2>> pins) {
  Scene s;
  s.forces.gravity = Vec3(0, 0, -9.81);
  ClothGridSpec g;
  g.rows = g.cols = n;
  g.spacing = spacing;
  g.origin = origin;
  g.axis_u = Vec3::UnitX();
  g.axis_v = v_axis;
  g.total_mass = mass;
  g.stiffness_b = ks;
  g.pins = std::move(pins);
  append_cloth(s, g);
  return s;
}

}  // namespace

std::vector<Conservative> conservative_scenes(std::uint64_t seed) { return {two_body(), free_cloth(seed)}; }

Scene twin_cloth(const Settings& s, const Vec3& origin, bool pinned) {
  const int n = s.twin_nodes;
  std::vector<std::array<int, 2>> pins;
  if (pinned) pins = {{0, 0}, {0, n - 1}};
  Scene sc = grid_cloth(n, s.twin_spacing, s.twin_mass, s.twin_stiffness, origin, Vec3::UnitY(), pins);
  sc.dt = s.twin_dt;
  return sc;
}

Scene falling_cloth(const Settings& s) {
  const double half = 0.5 * (s.twin_nodes - 1) * s.twin_spacing;
  Scene sc = twin_cloth(s, Vec3(-half, -half, s.fall_height), false);
  for (auto& k : sc.particles.elasticity) k = 0.0;
  sc.planes.push_back(make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), Vec2(2, 2), 0.5));
  return sc;
}

Scene classic_curtain(const Settings& s) {
  const int n = s.classic_nodes;
  std::vector<std::array<int, 2>> top;
  for (int c = 0; c < n; ++c) top.push_back({0, c});
  Scene sc = grid_cloth(n, s.classic_side / (n - 1), s.classic_mass, s.classic_stiffness, Vec3(0, 0, 1), -Vec3::UnitZ(),
                        top);
  sc.dt = s.classic_dt;
  return sc;
}

Scene with_load(const Scene& scene, double factor) {
  Scene s = scene;
  for (double& w : s.particles.inv_mass) w /= factor;
  return s;
}

Scene windy_cloth() {
  Scene s = grid_cloth(6, 0.1, 0.1, 100.0, Vec3::Zero(), Vec3::UnitY(), {{0, 0}, {0, 5}});
  s.dt = 0.01;
  Wind w;
  w.force = Vec3(0.01, 0, 0);
  s.forces.wind = w;
  s.forces.air_drag = 0.01;
  return s;
}

}  // namespace tecido::suites::drift
