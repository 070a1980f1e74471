// The plane suite's dynamic groups (comparisons/suites/plane/contact_time.*, drop.*) against the
// analytic drop: midpoint's bisected contact time within the tolerance of the root, symplectic
// Euler's off by its own O(h) error, a drop that never lands reported as missing by name, and the
// drop group's core columns (and Bullet's, in a reference build) against theory.h.
#include "comparisons/suites/plane/contact_time.h"
#include "comparisons/suites/plane/drop.h"
#include "comparisons/suites/plane/theory.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::suites::plane {
namespace {

ContactTimeSettings few() {
  ContactTimeSettings s;
  s.drops = 6;
  return s;
}

TEST(PlaneContactTime, DropStartsArePureFunctionsOfSeedAndIndex) {
  const ContactTimeSettings s = few();
  const DropStart a = drop_start(s, 9, 3), b = drop_start(s, 9, 3), c = drop_start(s, 9, 4);
  EXPECT_EQ(a.z0, b.z0);
  EXPECT_EQ(a.v, b.v);
  EXPECT_NE(a.z0, c.z0);
  for (int d = 0; d < 20; ++d) {
    const DropStart x = drop_start(s, 9, d);
    EXPECT_GE(x.z0, s.height_lo);
    EXPECT_LE(x.z0, s.height_hi);
    EXPECT_GE(x.v.z(), s.vz_lo);
    EXPECT_LE(x.v.z(), s.vz_hi);
    EXPECT_LE(std::abs(x.v.x()), s.v_horizontal);
  }
}

TEST(PlaneContactTime, MidpointsContactIsWithinTheToleranceOfTheRoot) {
  const ContactTimeSettings s = few();
  for (int level : {4, 12, 24}) {
    const ContactCellResult r = run_contact_cell(s, 11, IntegratorKind::Midpoint, 0.02, level);
    EXPECT_EQ(r.contacts, s.drops);
    EXPECT_EQ(r.first_missing, -1);
    EXPECT_EQ(r.tolerance, std::ldexp(0.02, -level));
    EXPECT_LE(r.max_error, r.tolerance) << level;
    EXPECT_GT(r.max_error, 0.0);
    EXPECT_GE(r.bisections, level);  // halving h down to h 2^-level takes at least `level` calls
    EXPECT_TRUE(missing_reason(s, r, "").empty());
  }
}

TEST(PlaneContactTime, SymplecticEulerStopsAtItsOwnError) {
  const ContactTimeSettings s = few();
  const ContactCellResult r = run_contact_cell(s, 11, IntegratorKind::Symplectic, 0.02, 24);
  EXPECT_EQ(r.contacts, s.drops);
  EXPECT_GT(r.max_error, 0.1 * 0.02);  // O(h), far above the tolerance h 2^-24
  EXPECT_LT(r.max_error, 2.0 * 0.02);
}

TEST(PlaneContactTime, ADropThatNeverLandsIsMissingByName) {
  ContactTimeSettings s = few();
  s.max_time = 0.05;  // shorter than any fall from 0.2 m or more
  const ContactCellResult r = run_contact_cell(s, 11, IntegratorKind::Midpoint, 0.01, 8);
  EXPECT_EQ(r.contacts, 0);
  EXPECT_EQ(r.first_missing, 0);
  EXPECT_EQ(missing_reason(s, r, ""), "drop 0 made no contact within 0.05 s (0 of 6 did)");
  EXPECT_EQ(missing_reason(s, r, "case 3 threw: x"), "case 3 threw: x");
  const ContactCellResult back = cell_from_json(io::Json::parse(cell_json(r).dump()));
  EXPECT_EQ(back.first_missing, 0);
  EXPECT_TRUE(std::isnan(back.bisections));
}

TEST(PlaneDrop, CoreLandsOnTimeAndReboundsToKSquaredZ0) {
  const DropSettings s;
  for (double z0 : {0.2, 3.0}) {
    const DropRow r = run_drop(s, z0);
    EXPECT_DOUBLE_EQ(r.t_exact, contact_time(z0, 0.0, s.gravity));
    EXPECT_DOUBLE_EQ(r.apex_exact, s.elasticity * s.elasticity * z0);
    EXPECT_NEAR(r.t_core, r.t_exact, s.dt * 1e-3);  // bisected to dt 2^-20 by default
    // The apex is the highest step end: below the true apex by at most g dt^2 / 8.
    EXPECT_LE(r.apex_core, r.apex_exact + 1e-7);
    EXPECT_GE(r.apex_core, r.apex_exact - s.gravity * s.dt * s.dt / 8.0 - 1e-7);
    EXPECT_DOUBLE_EQ(drop_duration(s, z0), r.t_exact + s.into_fall * rebound_flight(z0, s.elasticity, s.gravity));
    ASSERT_TRUE(r.bullet);
    EXPECT_NEAR(r.t_rigid, r.t_exact, s.dt);  // seen at a step end
    EXPECT_GT(r.apex_rigid, 0.5 * r.apex_exact);
    EXPECT_GT(r.node_margin, 0.0);
    EXPECT_FALSE(r.node_not_modelled.empty());
    const DropRow back = drop_from_json(io::Json::parse(drop_json(r).dump()));
    EXPECT_EQ(back.apex_core, r.apex_core);
    EXPECT_EQ(back.node_not_modelled, r.node_not_modelled);
  }
}

}  // namespace
}  // namespace tecido::suites::plane
