// PackedSprings (core/dynamics/packed_springs.h), the fast spring-force loop, against a plain
// implementation of eq. 10 written here, and against core's plain loop (accumulate_spring_forces),
// for every kernel the CPU supports: random cloths with damping and pins, arbitrary extra
// springs (short runs, reversed ends, coincident ends), runs longer than one block.
#include "core/dynamics/force_model.h"
#include "core/dynamics/packed_springs.h"
#include "core/scene/cloth_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using namespace tecido;

// Eq. 10 with damping, written the textbook way: u = d / |d|,
// f_i = (ks (|d| - l) + c (v_j - v_i) . u) u, f_j = -f_i; coincident ends give no force.
std::vector<Vec3> reference_forces(const std::vector<Spring>& springs, const std::vector<Vec3>& x,
                                   const std::vector<Vec3>& v) {
  std::vector<Vec3> f(x.size(), Vec3::Zero());
  for (const Spring& s : springs) {
    const Vec3 d = x[s.j] - x[s.i];
    const double len = d.norm();
    if (!(len > 0.0)) continue;
    const Vec3 u = d / len;
    const Vec3 fi = (s.stiffness * (len - s.rest_length) + s.damping * (v[s.j] - v[s.i]).dot(u)) * u;
    f[s.i] += fi;
    f[s.j] -= fi;
  }
  return f;
}

// The accelerations of force_model.h, written plainly: pinned -> 0, else g + (F + wind - c v) / m.
std::vector<Vec3> reference_accelerations(const ForceModel& m, const std::vector<double>& inv_mass, double t,
                                          const std::vector<Vec3>& x, const std::vector<Vec3>& v) {
  std::vector<Vec3> f = reference_forces(m.springs, x, v);
  std::vector<Vec3> a(x.size(), Vec3::Zero());
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (inv_mass[i] == 0.0) continue;
    Vec3 fi = f[i] - m.air_drag.value_or(0.0) * v[i];
    if (m.wind) fi += m.wind->at(t);
    a[i] = m.gravity.value_or(Vec3::Zero()) + inv_mass[i] * fi;
  }
  return a;
}

struct Case {
  Scene scene;
  std::vector<Vec3> x, v;
};

// A rows x cols cloth, jiggled, with random velocities, damping, pins and `extra` arbitrary springs.
Case random_cloth(int rows, int cols, double damping, int extra, unsigned seed) {
  Case c;
  ClothGridSpec spec;
  spec.rows = rows;
  spec.cols = cols;
  spec.spacing = 0.05;
  spec.origin = Vec3(0.2, -0.1, 1.0);
  spec.total_mass = 0.7;
  spec.stiffness_b = 120.0;
  spec.stiffness_a = 30.0;
  spec.damping = damping;
  spec.pins = {{0, 0}, {0, cols - 1}, {rows / 2, cols / 2}};
  append_cloth(c.scene, spec);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = static_cast<int>(c.scene.particles.size());
  std::uniform_int_distribution<int> node(0, n - 1);
  for (int k = 0; k < extra; ++k) {
    const int i = node(rng), j = node(rng);  // any order; i == j is a coincident spring
    c.scene.forces.springs.push_back(Spring{i, j, 50.0 * (1.5 + u(rng)), 0.04 * (1.5 + u(rng)), k % 2 ? 0.0 : 0.3});
  }
  c.x = c.scene.particles.x;
  c.v.resize(c.x.size());
  for (std::size_t i = 0; i < c.x.size(); ++i) {
    c.x[i] += 0.3 * spec.spacing * Vec3(u(rng), u(rng), u(rng));
    c.v[i] = Vec3(u(rng), u(rng), u(rng));
  }
  return c;
}

std::vector<SpringKernel> supported_kernels() {
  std::vector<SpringKernel> ks;
  for (SpringKernel k : {SpringKernel::Scalar, SpringKernel::SSE2, SpringKernel::AVX, SpringKernel::AVX512})
    if (spring_kernel_supported(k)) ks.push_back(k);
  return ks;
}

double max_norm(const std::vector<Vec3>& f) {
  double m = 0.0;
  for (const Vec3& fi : f) m = std::max(m, fi.norm());
  return m;
}

// Forces of every kernel: within 1e-12 (relative to the largest force) of the textbook form, and
// equal to core's plain loop (same operations, same per-particle order; exact where the compiler
// does not contract a*b+c into fused multiply-adds, as on x86-64).
void check_forces(const Case& c) {
  const std::vector<Spring>& springs = c.scene.forces.springs;
  const std::vector<Vec3> ref = reference_forces(springs, c.x, c.v);
  std::vector<Vec3> plain;
  accumulate_spring_forces(springs, c.x, c.v, plain);
  const double scale = max_norm(ref);
  ASSERT_GT(scale, 0.1);
  PackedSprings packed(springs);
  ASSERT_EQ(packed.size(), springs.size());
  for (SpringKernel k : supported_kernels()) {
    packed.set_kernel(k);
    ASSERT_EQ(packed.kernel(), k);
    packed.accumulate(c.x, c.v);
    for (std::size_t i = 0; i < c.x.size(); ++i) {
      const Vec3 got(packed.fx()[i], packed.fy()[i], packed.fz()[i]);
      EXPECT_LE((got - ref[i]).norm(), 1e-12 * scale) << spring_kernel_name(k) << " particle " << i;
#if defined(__x86_64__)
      EXPECT_EQ(got, plain[i]) << spring_kernel_name(k) << " particle " << i;
#else
      EXPECT_LE((got - plain[i]).norm(), 1e-13 * scale) << spring_kernel_name(k) << " particle " << i;
#endif
    }
  }
}

TEST(PackedSprings, CloudOfRunsMatchesPlainSpringForces) {
  // 7 x 9: runs of 8 and fewer, odd lengths (vector remainders); damped everywhere.
  check_forces(random_cloth(7, 9, 0.25, 0, 1));
  // Undamped (the benchmark's case), plus arbitrary springs: short runs take the scalar path,
  // reversed springs give negative offsets, damped and undamped runs alternate.
  check_forces(random_cloth(6, 11, 0.0, 40, 2));
  // 9 x 40: the vertical family is one run of 320 springs, longer than a block (256).
  check_forces(random_cloth(9, 40, 0.1, 7, 3));
  // Tiny cloth: every run shorter than any vector width.
  check_forces(random_cloth(2, 3, 0.2, 3, 4));
}

TEST(PackedSprings, RunsFollowTheClothFamilies) {
  // One run per row of each horizontal or diagonal family, one per vertical family.
  Case c = random_cloth(5, 8, 0.0, 0, 5);
  PackedSprings packed(c.scene.forces.springs);
  // Type B: horizontal 5 rows, vertical 1, diagonal 4, anti-diagonal 4; type A: 5, 1, 3, 3.
  EXPECT_EQ(packed.run_count(), 5u + 1 + 4 + 4 + 5 + 1 + 3 + 3);
}

TEST(PackedSprings, CoincidentAndNonFiniteEndsGiveNoForce) {
  // Eq. 10 has no direction for coincident ends: no force, as in the plain loop. A NaN end
  // (an unstable run) makes its springs' lengths NaN; those springs are skipped too, so the
  // other ends' forces stay what the remaining springs give.
  std::vector<Vec3> x(12), v(12, Vec3::Zero());
  std::vector<Spring> springs;
  for (int i = 0; i < 12; ++i) x[i] = Vec3(0.1 * i, 0.02 * i * i, 0.0);
  x[5] = x[4];  // spring 4-5 coincident
  x[9] = Vec3(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  for (int i = 0; i + 1 < 12; ++i) springs.push_back(Spring{i, i + 1, 10.0, 0.05, 0.0});
  std::vector<Vec3> plain;
  accumulate_spring_forces(springs, x, v, plain);
  PackedSprings packed(springs);
  for (SpringKernel k : supported_kernels()) {
    packed.set_kernel(k);
    packed.accumulate(x, v);
    for (int i = 0; i < 12; ++i) {
      if (i == 9) continue;  // the NaN particle itself
      const Vec3 got(packed.fx()[i], packed.fy()[i], packed.fz()[i]);
      EXPECT_EQ(got, plain[i]) << spring_kernel_name(k) << " particle " << i;
      EXPECT_TRUE(got.allFinite()) << spring_kernel_name(k) << " particle " << i;
    }
  }
}

TEST(PackedSprings, AccelerationsMatchPlainWithPinsWindDragAndGravity) {
  Case c = random_cloth(8, 13, 0.2, 5, 6);
  ForceModel& m = c.scene.forces;
  m.gravity = Vec3(0.3, 0.0, -9.81);
  m.air_drag = 0.05;
  m.wind = Wind{Vec3(0.02, 0.01, 0.0), true, Vec3::UnitZ(), 1.3, 0.4};
  const std::vector<double>& w = c.scene.particles.inv_mass;
  const double t = 0.37;
  const std::vector<Vec3> ref = reference_accelerations(m, w, t, c.x, c.v);
  std::vector<Vec3> plain;
  compute_accelerations(m, w, t, c.x, c.v, plain);
  const double scale = max_norm(ref);
  PackedSprings packed(m.springs);
  for (SpringKernel k : supported_kernels()) {
    packed.set_kernel(k);
    std::vector<Vec3> a;
    compute_accelerations(m, packed, w, t, c.x, c.v, a);
    ASSERT_EQ(a.size(), c.x.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (w[i] == 0.0) {
        EXPECT_EQ(a[i], Vec3::Zero()) << "pinned particle " << i;
        continue;
      }
      EXPECT_LE((a[i] - ref[i]).norm(), 1e-12 * scale) << spring_kernel_name(k) << " particle " << i;
#if defined(__x86_64__)
      EXPECT_EQ(a[i], plain[i]) << spring_kernel_name(k) << " particle " << i;
#endif
    }
  }
  // No springs at all: gravity, wind and drag only.
  ForceModel bare = m;
  bare.springs.clear();
  PackedSprings none(bare.springs);
  EXPECT_TRUE(none.empty());
  std::vector<Vec3> a0, p0;
  compute_accelerations(bare, none, w, t, c.x, c.v, a0);
  compute_accelerations(bare, w, t, c.x, c.v, p0);
  for (std::size_t i = 0; i < a0.size(); ++i) EXPECT_EQ(a0[i], p0[i]) << i;
}

}  // namespace
