// Bullet's classic soft body (reference/bullet_softbody.h): numbering, the kLST calibration
// against core's Hooke springs (static sag of a hanging cloth, core settled with air drag), and
// the self-collision option.
#include "reference/bullet_softbody.h"

#include "core/cloth/cloth_builder.h"
#include "core/dynamics/simulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <stdexcept>

namespace tecido::reference {
namespace {

const Vec3 kGravity(0, 0, -9.81);

// A curtain: rows hang down -z from the pinned top row, 0.3 m x 0.3 m, 0.1 kg, type B springs
// only, so its sag is set by stretch (what kLST controls), not by geometry.
Scene curtain(int n, double ks, double dt) {
  Scene s;
  s.dt = dt;
  s.forces.gravity = kGravity;
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

TEST(BulletClassic, NodesAreCoreParticlesInOrder) {
  Scene s = curtain(5, 100.0, 1e-3);
  s.particles.x[5] += Vec3(0.001, 0.002, -0.003);  // break the grid's regularity (row 1, col 0)
  ClassicSoftBodyOptions o;
  o.klst = 0.005;  // soft enough that every free node visibly sags
  o.kdp = 0.05;
  ClassicSoftBody sb(s, o);
  const auto x = sb.positions();
  ASSERT_EQ(x.size(), s.particles.size());
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_EQ(x[i], s.particles.x[i]) << "node " << i;
  for (int k = 0; k < 500; ++k) ASSERT_TRUE(sb.step());
  const auto y = sb.positions();
  for (int col = 0; col < 5; ++col) EXPECT_EQ(y[col], s.particles.x[col]) << "pinned node " << col << " moved";
  // Lower rows sag more: node order follows rows (a renumbering would break this).
  for (int row = 2; row < 5; ++row) {
    const double drop_here = s.particles.x[row * 5 + 2].z() - y[row * 5 + 2].z();
    const double drop_above = s.particles.x[(row - 1) * 5 + 2].z() - y[(row - 1) * 5 + 2].z();
    EXPECT_GT(drop_here, drop_above) << "row " << row;
    EXPECT_GT(drop_above, 0.0) << "row " << row - 1;
  }
}

// The acceptance case: calibrate kLST so Bullet's settled sag matches core's, then settle a
// fresh classic body with that kLST and compare sags.
TEST(BulletClassic, CalibratedHangingClothSagMatchesCore) {
  const Scene scene = curtain(6, 100.0, 1e-3);
  SagCalibrationOptions opt;  // piterations 10, kDP 0.05, core drag 10/s x mean mass
  SagCalibration cal;
  const double klst = calibrate_klst_for_sag(scene, opt, &cal);
  std::cout << "[bullet-classic] kLST calibration (6x6 curtain, ks = 100 N/m, dt = 1 ms, piterations = "
            << cal.piterations << ", kDP = " << cal.kdp << "): kLST = " << cal.klst << ", core sag = " << cal.core_sag
            << " m, Bullet sag = " << cal.bullet_sag << " m, error = " << cal.sag_error << " m ("
            << 100.0 * cal.relative_error << " %), sag with kLST = 1: " << cal.sag_at_klst_1 << " m, "
            << cal.evaluations << " Bullet settles; settled shapes differ by " << cal.shape_rms << " m RMS, "
            << cal.shape_max << " m at most\n";
  RecordProperty("klst", std::to_string(cal.klst));
  RecordProperty("sag_relative_error", std::to_string(cal.relative_error));
  EXPECT_EQ(klst, cal.klst);
  EXPECT_TRUE(cal.core_settled);
  EXPECT_TRUE(cal.bullet_settled);
  ASSERT_TRUE(cal.bracketed);
  EXPECT_GT(cal.core_sag, 1e-3);  // a sag worth calibrating on
  EXPECT_LE(cal.relative_error, opt.relative_tolerance);
  EXPECT_LT(cal.klst, 1.0);
  // The default kLST = 1 is measurably stiffer than core: the calibration did something.
  EXPECT_LT(cal.sag_at_klst_1, 0.9 * cal.core_sag);

  // A fresh body with the calibrated kLST, settled with damping, sags like core.
  ClassicSoftBodyOptions co;
  co.klst = klst;
  co.piterations = opt.piterations;
  co.kdp = opt.kdp;
  ClassicSoftBody sb(scene, co);
  double speed = 1.0;
  for (int k = 0; k < 20000 && speed > opt.rest_speed; ++k) {
    ASSERT_TRUE(sb.step());
    speed = 0.0;
    for (const Vec3& v : sb.velocities()) speed = std::max(speed, v.norm());
  }
  EXPECT_LT(speed, opt.rest_speed) << "did not settle";
  const double sag = mean_sag(scene, sb.positions());
  EXPECT_NEAR(sag, cal.core_sag, opt.relative_tolerance * cal.core_sag);
}

// A step too large for core's springs: the calibration must fail loudly, not match a NaN sag.
TEST(BulletClassic, CalibrationRefusesAnUnstableCoreRun) {
  const Scene scene = curtain(6, 100.0, 1.0 / 240.0);
  EXPECT_THROW(calibrate_klst_for_sag(scene), std::runtime_error);
}

TEST(BulletClassic, ReportsWhatItModelsDifferently) {
  Scene s = curtain(4, 100.0, 1e-3);
  s.forces.air_drag = 0.01;
  s.forces.springs[0].damping = 0.1;
  ClassicSoftBody sb(s);
  const auto notes = sb.not_modelled();
  auto has = [&](const std::string& prefix) {
    for (const auto& n : notes)
      if (n.rfind(prefix, 0) == 0) return true;
    return false;
  };
  EXPECT_TRUE(has("Hooke springs"));
  EXPECT_TRUE(has("air_drag"));
  EXPECT_TRUE(has("spring damping"));
  EXPECT_FALSE(has("wind"));
  EXPECT_FALSE(has("self-collision"));
}

// A bounded plane becomes a static box behind it; a falling patch stops on it near the margin.
TEST(BulletClassic, PlaneStopsAFallingPatch) {
  Scene s;
  s.dt = 1.0 / 240.0;
  s.forces.gravity = kGravity;
  ClothGridSpec c;
  c.rows = 3;
  c.cols = 3;
  c.spacing = 0.1;
  c.origin = Vec3(-0.1, -0.1, 0.1);
  c.total_mass = 0.1;
  c.stiffness_b = 50.0;
  append_cloth(s, c);
  s.planes.push_back(make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), Vec2(0.5, 0.5), 0.5));
  ClassicSoftBodyOptions o;
  o.kdp = 0.02;
  ClassicSoftBody sb(s, o);
  for (int k = 0; k < 240; ++k) ASSERT_TRUE(sb.step());
  double zmin = 1e9, zmax = -1e9;
  for (const Vec3& x : sb.positions()) {
    zmin = std::min(zmin, x.z());
    zmax = std::max(zmax, x.z());
  }
  std::cout << "[bullet-classic] patch on a plane after 1 s: node heights " << zmin << " .. " << zmax
            << " m (collision margin " << sb.plane_contact_offset() << " m)\n";
  for (const Vec3& x : sb.positions()) {
    EXPECT_GT(x.z(), -1e-3) << "fell through the plane";
    EXPECT_LT(x.z(), sb.plane_contact_offset() + 0.01) << "did not reach the plane";
  }
}

// Self-collision (off by default): clusters per triangle and the cluster collider run every step.
// A cloth laid over itself in two layers 2 cm apart and pushed together must not pass through.
TEST(BulletClassic, SelfCollisionOptionKeepsTwoLayersApart) {
  Scene s;
  s.dt = 1.0 / 240.0;
  // Two 3x3 patches (one Scene, one body), the upper one moving down onto the lower one.
  for (int layer = 0; layer < 2; ++layer) {
    ClothGridSpec c;
    c.rows = 3;
    c.cols = 3;
    c.spacing = 0.05;
    c.origin = Vec3(0, 0, 0.02 * layer);
    c.total_mass = 0.02;
    c.stiffness_b = 50.0;
    if (layer == 0) c.pins = {{0, 0}, {0, 2}, {2, 0}, {2, 2}};
    append_cloth(s, c);
  }
  for (int i = 9; i < 18; ++i) s.particles.v[i] = Vec3(0, 0, -0.5);
  ClassicSoftBodyOptions on;
  on.self_collision = true;
  ClassicSoftBodyOptions off;
  ClassicSoftBody with(s, on), without(s, off);
  bool mentions = false;
  for (const auto& n : with.not_modelled()) mentions = mentions || n.rfind("self-collision", 0) == 0;
  EXPECT_TRUE(mentions);
  for (int k = 0; k < 48; ++k) {
    ASSERT_TRUE(with.step());
    ASSERT_TRUE(without.step());
  }
  // Centre node of each layer: 4 (lower), 13 (upper).
  const double gap_with = with.positions()[13].z() - with.positions()[4].z();
  const double gap_without = without.positions()[13].z() - without.positions()[4].z();
  std::cout << "[bullet-classic] layer gap after 0.2 s: with self-collision " << gap_with << " m, without "
            << gap_without << " m\n";
  EXPECT_LT(gap_without, 0.0);  // without it the upper layer passes through
  EXPECT_GT(gap_with, 0.0);
}

}  // namespace
}  // namespace tecido::reference
