// The cloth builder (seed 2.1, 3.1.2): masses split by area, spring families counted by hand,
// internal forces summing to zero, and a hanging cloth that comes to rest only with air drag.
#include "core/cloth/mesh_topology.h"
#include "core/dynamics/force_model.h"
#include "core/scene/cloth_builder.h"
#include "core/simulation/simulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace tecido {
namespace {

ClothGridSpec grid(int rows, int cols, double spacing, double mass, double kb, double ka) {
  ClothGridSpec s;
  s.rows = rows;
  s.cols = cols;
  s.spacing = spacing;
  s.total_mass = mass;
  s.stiffness_b = kb;
  s.stiffness_a = ka;
  return s;
}

double mass_of(const Particles& p, int i) { return p.inv_mass[i] > 0 ? 1.0 / p.inv_mass[i] : 0.0; }

// 3 x 3 nodes, 8 equal triangles: each vertex gets total/24 per incident triangle. Incident
// triangles counted by hand from the documented split (a,b,d), (a,d,e) of each quad:
//   2 3 1
//   3 6 3
//   1 3 2
TEST(ClothBuilder, MassSplitByAreaThenVertices) {
  Scene s;
  append_cloth(s, grid(3, 3, 0.5, 2.4, 1.0, 0.0));
  const int count[9] = {2, 3, 1, 3, 6, 3, 1, 3, 2};
  double sum = 0.0;
  for (int i = 0; i < 9; ++i) {
    EXPECT_NEAR(mass_of(s.particles, i), 2.4 / 24.0 * count[i], 1e-15) << i;
    sum += mass_of(s.particles, i);
  }
  EXPECT_NEAR(sum, 2.4, 1e-14);
  // A larger, non-square grid: the masses sum to the total.
  Scene t;
  append_cloth(t, grid(7, 11, 0.03, 0.37, 1.0, 1.0));
  double total = 0.0;
  for (std::size_t i = 0; i < t.particles.size(); ++i) total += mass_of(t.particles, static_cast<int>(i));
  EXPECT_NEAR(total, 0.37, 1e-14);
}

// rows = 3, cols = 4. Type B: horizontal rows*(cols-1) = 9, vertical (rows-1)*cols = 8,
// diagonal and anti-diagonal (rows-1)*(cols-1) = 6 each. Type A: horizontal rows*(cols-2) = 6,
// vertical (rows-2)*cols = 4, diagonal and anti-diagonal (rows-2)*(cols-2) = 2 each.
TEST(ClothBuilder, SpringFamiliesCountedByHand) {
  Scene s;
  append_cloth(s, grid(3, 4, 1.0, 1.0, 5.0, 2.0));
  const auto& sp = s.forces.springs;
  ASSERT_EQ(sp.size(), 9u + 8 + 6 + 6 + 6 + 4 + 2 + 2);
  struct Family {
    int count, dr, dc;
    double k, len;
  } fam[] = {{9, 0, 1, 5, 1},        {8, 1, 0, 5, 1},        {6, 1, 1, 5, std::sqrt(2.0)}, {6, 1, -1, 5, std::sqrt(2.0)},
             {6, 0, 2, 2, 2},        {4, 2, 0, 2, 2},        {2, 2, 2, 2, std::sqrt(8.0)}, {2, 2, -2, 2, std::sqrt(8.0)}};
  std::size_t k = 0;
  for (const Family& f : fam) {
    for (int n = 0; n < f.count; ++n, ++k) {
      const int ri = sp[k].i / 4, ci = sp[k].i % 4, rj = sp[k].j / 4, cj = sp[k].j % 4;
      EXPECT_EQ(rj - ri, f.dr) << k;
      EXPECT_EQ(cj - ci, f.dc) << k;
      EXPECT_EQ(sp[k].stiffness, f.k) << k;
      EXPECT_NEAR(sp[k].rest_length, f.len, 1e-15) << k;
    }
  }
  EXPECT_EQ(s.triangles.size(), 2u * 2 * 3);
}

TEST(ClothBuilder, InternalSpringForcesSumToZero) {
  Scene s;
  ClothGridSpec spec = grid(6, 5, 0.2, 1.0, 30.0, 7.0);
  spec.damping = 0.4;
  append_cloth(s, spec);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-0.08, 0.08);
  std::vector<Vec3> x = s.particles.x, v(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] += Vec3(u(rng), u(rng), u(rng));
    v[i] = Vec3(u(rng), u(rng), u(rng)) * 10.0;
  }
  std::vector<Vec3> f;
  accumulate_spring_forces(s.forces.springs, x, v, f);
  Vec3 sum = Vec3::Zero(), torque = Vec3::Zero();
  double scale = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sum += f[i];
    torque += x[i].cross(f[i]);
    scale += f[i].norm();
  }
  ASSERT_GT(scale, 1.0);
  EXPECT_LT(sum.norm(), 1e-13 * scale);
  EXPECT_LT(torque.norm(), 1e-13 * scale);  // central forces: no net torque either
}

// A 7 x 7 cloth hanging from its two top corners. With linear drag c the mechanical energy
// decays (dE/dt = -c sum |v|^2), so after 15 s the kinetic energy is tiny; without drag the
// symplectic integrator keeps the energy (it does not dissipate), and the cloth keeps swinging
// with kinetic energy of the order of the potential energy it released.
struct Hanging {
  double ke_end = 0.0;      // kinetic energy at the end [J]
  double ke_max_last = 0.0; // max over the last 2 s
  double pe_released = 0.0; // gravity + spring potential energy released since t = 0 [J]
};

Hanging hang(double drag) {
  Scene s;
  s.dt = 0.002;
  s.forces.gravity = Vec3(0, 0, -9.81);
  if (drag > 0) s.forces.air_drag = drag;
  ClothGridSpec spec = grid(7, 7, 0.1, 0.49, 60.0, 20.0);
  spec.axis_u = Vec3::UnitX();
  spec.axis_v = Vec3::UnitY();  // starts horizontal: it swings down
  spec.pins = {{0, 0}, {0, 6}};
  append_cloth(s, spec);
  auto energy_pot = [&](const Particles& p) {
    double e = spring_potential_energy(s.forces.springs, p.x);
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.inv_mass[i] > 0) e += 9.81 * p.x[i].z() / p.inv_mass[i];
    return e;
  };
  auto energy_kin = [&](const Particles& p) {
    double e = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.inv_mass[i] > 0) e += 0.5 * p.v[i].squaredNorm() / p.inv_mass[i];
    return e;
  };
  Simulation sim(s);
  const double pe0 = energy_pot(sim.particles());
  Hanging h;
  const long long n = static_cast<long long>(std::llround(15.0 / s.dt));
  for (long long k = 1; k <= n; ++k) {
    sim.step();
    if (k > n - static_cast<long long>(std::llround(2.0 / s.dt))) h.ke_max_last = std::max(h.ke_max_last, energy_kin(sim.particles()));
  }
  h.ke_end = energy_kin(sim.particles());
  h.pe_released = pe0 - energy_pot(sim.particles());
  return h;
}

TEST(ClothBuilder, HangingClothComesToRestWithDragOnly) {
  const Hanging with = hang(0.02), without = hang(0.0);
  ASSERT_GT(with.pe_released, 0.5);  // it fell: about 0.49 kg over ~0.3 m
  // With drag (velocity time constant m/c = 0.01/0.02 = 0.5 s per particle; 15 s = 30 of them).
  EXPECT_LT(with.ke_max_last, 1e-8 * with.pe_released);
  // Without: still swinging with a sizeable share of the released energy.
  EXPECT_GT(without.ke_max_last, 0.05 * without.pe_released);
  EXPECT_GT(without.ke_end + without.ke_max_last, 1e4 * (with.ke_end + with.ke_max_last));
}

// Border distance on the builder's grid: min(r, c, rows-1-r, cols-1-c) (mesh_topology.h).
TEST(MeshTopology, BorderDistanceOnTheGridIsTheDistanceToTheNearestSide) {
  Scene s;
  append_cloth(s, grid(9, 12, 1.0, 1.0, 1.0, 0.0));
  const MeshTopology t = build_mesh_topology(static_cast<int>(s.particles.size()), s.triangles);
  for (int r = 0; r < 9; ++r)
    for (int c = 0; c < 12; ++c)
      EXPECT_EQ(t.border_distance[r * 12 + c], std::min(std::min(r, c), std::min(8 - r, 11 - c))) << r << "," << c;
  // Edges: horizontal 9*11 + vertical 8*12 + diagonal 8*11; boundary edges 2*(11+8).
  EXPECT_EQ(t.edges.size(), 9u * 11 + 8 * 12 + 8 * 11);
  int boundary = 0;
  for (int n : t.edge_triangles) boundary += n == 1;
  EXPECT_EQ(boundary, 2 * (11 + 8));
  // Interior node: six neighbours (left, right, up, down, and the a-d diagonal both ways).
  const int v = 4 * 12 + 5;
  std::vector<int> nb(t.adj.begin() + t.adj_start[v], t.adj.begin() + t.adj_start[v + 1]);
  EXPECT_EQ(nb, (std::vector<int>{v - 13, v - 12, v - 1, v + 1, v + 12, v + 13}));
}

}  // namespace
}  // namespace tecido
