// Bullet's engines as the tradeoff suite runs them (run_deformable_twin, run_classic_soft_body,
// the kLST calibration's secant start): checked against core on the suite's kind of scene, a
// curtain pinned at its two top corners with gravity in its plane, small enough to be fast.
// Truths: core's symplectic Euler (the deformable twin's own method), core's RK4 at a small step
// (the converged motion), step halving (the integrator's order) and core's settled sag.
#include "reference/bullet_deformable.h"
#include "reference/bullet_softbody.h"

#include "core/cloth/cloth_builder.h"
#include "core/dynamics/simulation.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <optional>
#include <thread>

namespace tecido::reference {
namespace {

// The tradeoff suite's curtain (comparisons/suites/tradeoff_suite.h, hanging_cloth): n x n nodes,
// 1 m x 1 m in the plane y = 0, pinned at (0, 0) and (0, n-1), 0.1 kg, type B 1 N/m, type A
// 0.5 N/m, no damping, gravity -9.81 z. For n = 8 its springs' highest frequency is below
// 2 / 2^-6 s, so h0 = 2^-6 s is the suite's first step for it.
Scene curtain(int n) {
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

constexpr int kN = 8;
const double kH0 = std::ldexp(1.0, -6);  // [s]
constexpr double kT = 1.0;               // [s]

std::vector<Vec3> core_run(const Scene& scene, IntegratorKind kind, double h, double seconds) {
  Scene s = scene;
  s.integrator = kind;
  s.dt = h;
  Simulation sim(s);
  const long long n = std::llround(seconds / h);
  for (long long i = 0; i < n; ++i) EXPECT_TRUE(sim.step());
  return sim.particles().x;
}

double rms(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  EXPECT_EQ(a.size(), b.size());
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]).squaredNorm();
  return std::sqrt(s / static_cast<double>(a.size()));
}

// The converged motion at t = 1 s: RK4 at h0 / 64 (its error, by halving, is below 1e-10 m).
const std::vector<Vec3>& reference_motion() {
  static const std::vector<Vec3> x = core_run(curtain(kN), IntegratorKind::RK4, kH0 / 64, kT);
  return x;
}

TEST(BulletTradeoff, DeformableTwinIsCoreSymplecticEulerOnTheCurtain) {
  const Scene s = curtain(kN);
  for (double h : {kH0, kH0 / 8}) {
    const auto bullet = run_deformable_twin(s, h, kT);
    ASSERT_TRUE(bullet.has_value()) << "h = " << h;
    const auto core = core_run(s, IntegratorKind::Symplectic, h, kT);
    const double d = rms(*bullet, core);
    std::cout << "[bullet-tradeoff] deformable twin vs core symplectic, 8x8 curtain, h = " << h << " s, 1 s: " << d
              << " m RMS\n";
    EXPECT_LT(d, 1e-12) << "h = " << h;
  }
}

TEST(BulletTradeoff, DeformableTwinErrorIsFirstOrderInTheStep) {
  const Scene s = curtain(kN);
  const auto& ref = reference_motion();
  std::vector<double> err;
  for (int j = 2; j <= 4; ++j) {
    const auto x = run_deformable_twin(s, kH0 / std::ldexp(1.0, j), kT);
    ASSERT_TRUE(x.has_value());
    err.push_back(rms(*x, ref));
  }
  for (std::size_t j = 1; j < err.size(); ++j) {
    const double order = std::log2(err[j - 1] / err[j]);
    std::cout << "[bullet-tradeoff] deformable twin error " << err[j - 1] << " -> " << err[j]
              << " m on halving the step: observed order " << order << "\n";
    EXPECT_GT(order, 0.85);  // symplectic Euler: first order in position
    EXPECT_LT(order, 1.15);
  }
}

TEST(BulletTradeoff, ExplicitTwinDoesNotDependOnTheSolverIterationCap) {
  // The explicit step solves M dv = h f with a mass preconditioner: one Krylov iteration is exact.
  const Scene s = curtain(kN);
  DeformableTwinOptions one;
  one.krylov_iterations = 1;
  const auto a = run_deformable_twin(s, kH0, kT, one);
  const auto b = run_deformable_twin(s, kH0, kT);
  ASSERT_TRUE(a && b);
  EXPECT_LT(rms(*a, *b), 1e-13);
}

TEST(BulletTradeoff, ImplicitWorldIsStableBeyondTheExplicitLimitAndConvergesAtFirstOrder) {
  const Scene s = curtain(kN);
  const auto& ref = reference_motion();
  DeformableTwinOptions imp;
  imp.implicit = true;
  imp.krylov_iterations = 16;
  // At 4 h0 symplectic Euler blows up; linearised backward Euler stays bounded (and damped).
  EXPECT_FALSE(run_deformable_twin(s, 4 * kH0, kT).has_value());
  const auto big = run_deformable_twin(s, 4 * kH0, kT, imp);
  ASSERT_TRUE(big.has_value());
  EXPECT_LT(rms(*big, ref), 0.5);
  std::vector<double> err;
  for (int j = 2; j <= 4; ++j) {
    const auto x = run_deformable_twin(s, kH0 / std::ldexp(1.0, j), kT, imp);
    ASSERT_TRUE(x.has_value());
    err.push_back(rms(*x, ref));
  }
  for (std::size_t j = 1; j < err.size(); ++j) {
    const double order = std::log2(err[j - 1] / err[j]);
    std::cout << "[bullet-tradeoff] implicit world (16 CG iterations) error " << err[j - 1] << " -> " << err[j]
              << " m: observed order " << order << "\n";
    EXPECT_GT(order, 0.7);
    EXPECT_LT(order, 1.3);
  }
}

TEST(BulletTradeoff, RunsAreBitForBitReproducibleAlsoOnConcurrentThreads) {
  // The suite's front points must rerun bit-identically; Bullet's runs are single-threaded and
  // start from a freshly built world, so they do.
  const Scene s = curtain(kN);
  DeformableTwinOptions imp;
  imp.implicit = true;
  imp.krylov_iterations = 4;
  ClassicSoftBodyOptions cls;
  cls.klst = 0.05;
  cls.piterations = 4;
  cls.kdp = 0.0;
  const auto a1 = run_deformable_twin(s, kH0, kT), a2 = run_deformable_twin(s, kH0, kT);
  const auto b1 = run_deformable_twin(s, kH0, kT, imp), b2 = run_deformable_twin(s, kH0, kT, imp);
  const auto c1 = run_classic_soft_body(s, kH0, kT, cls), c2 = run_classic_soft_body(s, kH0, kT, cls);
  ASSERT_TRUE(a1 && a2 && b1 && b2 && c1 && c2);
  EXPECT_EQ(*a1, *a2);
  EXPECT_EQ(*b1, *b2);
  EXPECT_EQ(*c1, *c2);
  // The same runs on concurrent threads (the suite may run points in parallel): each world is its
  // own, so the results are unchanged.
  std::optional<std::vector<Vec3>> a3, b3, c3;
  std::thread ta([&] { a3 = run_deformable_twin(s, kH0, kT); });
  std::thread tb([&] { b3 = run_deformable_twin(s, kH0, kT, imp); });
  std::thread tc([&] { c3 = run_classic_soft_body(s, kH0, kT, cls); });
  ta.join();
  tb.join();
  tc.join();
  ASSERT_TRUE(a3 && b3 && c3);
  EXPECT_EQ(*a3, *a1);
  EXPECT_EQ(*b3, *b1);
  EXPECT_EQ(*c3, *c1);
}

TEST(BulletTradeoff, HugeStepReturnsNothingQuicklyInsteadOfAClampedCloth) {
  // Bullet zeroes NaN velocity increments and clamps speeds, so a blown-up run stays finite; the
  // stray test must still call it unstable, and the fixed step count must end it.
  const Scene s = curtain(kN);
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_FALSE(run_deformable_twin(s, 0.25, 10.0).has_value());
  EXPECT_FALSE(run_deformable_twin(s, 16 * kH0, kT).has_value());
  // The classic body keeps positions bounded by projection: at a huge step it either returns a
  // bounded (wrong) cloth or nothing, but it must return.
  ClassicSoftBodyOptions o;
  o.klst = 1.0;
  o.kdp = 0.0;
  const auto c = run_classic_soft_body(s, 0.25, 10.0, o);
  if (c) {
    for (const Vec3& x : *c) EXPECT_TRUE(x.allFinite());
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 60.0);
}

// The classic body with kLST calibrated (secant start) at each number of position sweeps: its
// static sag matches core's, and its motion at t = 1 s is as far from the converged spring motion
// whatever the sweeps: more sweeps do not make it worse (beyond 25 %), nor much better (the gap is
// the position-based model's, not the solver's).
TEST(BulletTradeoff, CalibratedClassicErrorDoesNotGrowWithMoreSweeps) {
  Scene s = curtain(kN);
  s.dt = kH0;
  const auto& ref = reference_motion();
  std::vector<double> err;
  for (int it : {1, 4, 16}) {
    SagCalibrationOptions o;
    o.piterations = it;
    o.kdp = 6.4 * kH0;
    o.rest_speed = 1e-4;
    o.relative_tolerance = 1e-2;
    o.max_time = 30.0;
    o.klst_guess = 0.2 / it;
    SagCalibration cal;
    const double klst = calibrate_klst_for_sag(s, o, &cal);
    EXPECT_TRUE(cal.bracketed);
    EXPECT_LE(cal.relative_error, 1e-2) << "sweeps " << it;
    EXPECT_LE(cal.evaluations, 6) << "sweeps " << it;
    ClassicSoftBodyOptions co;
    co.klst = klst;
    co.piterations = it;
    co.kdp = 0.0;
    const auto x = run_classic_soft_body(s, kH0, kT, co);
    ASSERT_TRUE(x.has_value());
    err.push_back(rms(*x, ref));
    std::cout << "[bullet-tradeoff] classic, " << it << " sweeps: kLST " << klst << " (" << cal.evaluations
              << " settles, sag " << cal.bullet_sag << " vs core " << cal.core_sag << " m), error at 1 s " << err.back()
              << " m\n";
  }
  EXPECT_LE(err[1], 1.25 * err[0]);
  EXPECT_LE(err[2], 1.25 * err[0]);
}

TEST(BulletTradeoff, SecantStartFindsTheSameKlstAsBisection) {
  Scene s = curtain(kN);
  s.dt = kH0;
  SagCalibrationOptions o;
  o.piterations = 4;
  o.kdp = 6.4 * kH0;
  o.rest_speed = 1e-4;
  o.relative_tolerance = 1e-3;
  o.max_time = 30.0;
  SagCalibration bis, sec;
  const double k_bis = calibrate_klst_for_sag(s, o, &bis);
  o.klst_guess = 0.2;  // 4x off on purpose
  const double k_sec = calibrate_klst_for_sag(s, o, &sec);
  std::cout << "[bullet-tradeoff] kLST by bisection " << k_bis << " (" << bis.evaluations << " settles), by secant "
            << k_sec << " (" << sec.evaluations << " settles)\n";
  EXPECT_NEAR(k_sec / k_bis, 1.0, 0.01);
  EXPECT_LT(sec.evaluations, bis.evaluations);
  EXPECT_TRUE(std::isnan(sec.sag_at_klst_1));
}

}  // namespace
}  // namespace tecido::reference
