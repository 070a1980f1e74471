#pragma once
// The tradeoff suite's kind of scene for the reference-engine tests, small enough to be fast: a
// curtain of n x n nodes, 1 m x 1 m in the plane y = 0, pinned at its top corners (0, 0) and
// (0, n-1), 0.1 kg, type B springs 1 N/m, type A 0.5 N/m, no damping, gravity -9.81 z (the same
// as comparisons/suites/tradeoff/curtain.h, written out here so the reference tests need nothing
// from comparisons/). For n = 8 its springs' highest frequency is below 2 / 2^-6 s, so h0 = 2^-6 s
// is the suite's first step for it. Core's runs of it are the truths the Bullet tests compare with.
#include "core/scene/cloth_builder.h"
#include "core/simulation/simulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tecido::testing {

inline Scene curtain(int n) {
  Scene s;
  ClothGridSpec g;
  g.rows = g.cols = n;
  g.spacing = 1.0 / (n - 1);
  g.origin = Vec3::Zero();
  g.axis_u = Vec3::UnitX();
  g.axis_v = -Vec3::UnitZ();
  g.total_mass = 0.1;
  g.stiffness_b = 1.0;
  g.stiffness_a = 0.5;
  g.pins = {{0, 0}, {0, n - 1}};
  append_cloth(s, g);
  s.forces.gravity = Vec3(0, 0, -9.81);
  return s;
}

/// The classic soft body's calibration curtain (test_klst_calibration, test_bullet_softbody): n x n
/// nodes hanging down -z from the pinned top row, 0.3 m x 0.3 m, 0.1 kg, type B springs ks only,
/// so its sag is set by stretch (what kLST controls), not by geometry; gravity -9.81 z, step dt.
inline Scene stretch_curtain(int n, double ks, double dt) {
  Scene s;
  s.dt = dt;
  s.forces.gravity = Vec3(0, 0, -9.81);
  ClothGridSpec c;
  c.rows = n;
  c.cols = n;
  c.spacing = 0.3 / (n - 1);
  c.origin = Vec3(0, 0, 1);
  c.axis_u = Vec3::UnitX();
  c.axis_v = -Vec3::UnitZ();
  c.total_mass = 0.1;
  c.stiffness_b = ks;
  for (int col = 0; col < n; ++col) c.pins.push_back({0, col});
  append_cloth(s, c);
  return s;
}

constexpr int kCurtainN = 8;
inline const double kCurtainH0 = std::ldexp(1.0, -6);  // [s]
constexpr double kCurtainT = 1.0;                      // [s]

/// Core with `kind` at step h for `seconds`; every step must stay finite.
inline std::vector<Vec3> core_run(const Scene& scene, IntegratorKind kind, double h, double seconds) {
  Scene s = scene;
  s.integrator = kind;
  s.dt = h;
  Simulation sim(s);
  const long long n = std::llround(seconds / h);
  for (long long i = 0; i < n; ++i) EXPECT_TRUE(sim.step());
  return sim.particles().x;
}

/// RMS over nodes of |a_i - b_i|.
inline double rms(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  EXPECT_EQ(a.size(), b.size());
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]).squaredNorm();
  return std::sqrt(s / static_cast<double>(a.size()));
}

/// The curtain's converged motion at t = 1 s: RK4 at h0 / 64 (its error, by halving, is below 1e-10 m).
inline const std::vector<Vec3>& curtain_reference_motion() {
  static const std::vector<Vec3> x = core_run(curtain(kCurtainN), IntegratorKind::RK4, kCurtainH0 / 64, kCurtainT);
  return x;
}

}  // namespace tecido::testing
