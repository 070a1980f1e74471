// The plane suite's prose (plane_report.*, contact_time_report.*, drop_report.*) is derived from
// its tables: planted tables that contradict a conclusion flip it, and failed parts are named.
#include "comparisons/suites/plane/contact_time_report.h"
#include "comparisons/suites/plane/drop_report.h"
#include "comparisons/suites/plane/plane_report.h"

#include <gtest/gtest.h>

namespace tecido::suites::plane {
namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

AgreementTable two_engines() {
  AgreementTable t = agreement::empty_table(categories().size(), {"core", "core-seed"});
  for (std::size_t c = 0; c < categories().size(); ++c)
    for (std::size_t e = 0; e < 2; ++e) {
      Tally& x = t.tally[c][e];
      x.cases = x.agree = 10;
      x.both_hit = 4;
      x.max_t_error = 1e-16;
    }
  return t;
}

TEST(PlaneReport, AgreementConclusionsFollowTheTable) {
  AgreementTable t = two_engines();
  std::string md = agreement_conclusions(categories(), t, "exact");
  EXPECT_TRUE(has(md, "- `core` (checked on every group): agrees with the referee on every evaluated case")) << md;
  EXPECT_TRUE(has(md, "its floating-point filter decided every case")) << md;
  EXPECT_TRUE(has(md, "- `core-seed` (reported, not checked): agrees")) << md;
  // core-seed: one false hit on edge (category 1), two misses on corner (2); core's filter used its
  // exact path on 3 edge cases.
  t.tally[1][1].agree = 9, t.tally[1][1].false_hits = 1;
  t.tally[2][1].agree = 8, t.tally[2][1].misses = 2;
  t.tally[1][0].exact_path = 3;
  md = agreement_conclusions(categories(), t, "exact");
  EXPECT_TRUE(has(md, "- `core-seed` (reported, not checked): false hits on edge (1 of 10); misses on corner (2 of 10)")) << md;
  EXPECT_TRUE(has(md, "left cases to the exact path on edge (3 of 10)")) << md;
  // The grazing category's t error is named apart (its group checks agreement only).
  t.tally[3][0].max_t_error = 2e-5;
  md = agreement_conclusions(categories(), t, "exact");
  EXPECT_TRUE(has(md, "largest |t - t_exact| where both hit 1.00e-16 (2.00e-05 on grazing")) << md;
}

TEST(PlaneReport, AFailedCategoryIsShownWithItsReason) {
  AgreementTable t = two_engines();
  t.error[2] = "case 7 threw: broken generator";
  const std::string md = agreement_table(categories(), t);
  EXPECT_TRUE(has(md, "| core | corner | failed |")) << md;
  EXPECT_TRUE(has(md, "Category `corner` failed: case 7 threw: broken generator")) << md;
  EXPECT_TRUE(has(md, "corner failed")) << md;  // in the referee's hits line
  EXPECT_TRUE(has(agreement_conclusions(categories(), t, "exact"), "agrees with the referee on every evaluated case"));
  EXPECT_TRUE(agreement_json(categories(), t)["core"]["corner"].contains("error"));
  EXPECT_TRUE(agreement_json(categories(), t)["core"]["edge"]["max_t_error"].is_number());
}

/// Midpoint and symplectic at two steps and three levels, every error at half the tolerance.
ContactTable planted(const ContactTimeSettings& s) {
  ContactTable t = empty_contact_table(s);
  for (std::size_t i = 0; i < 2; ++i)
    for (std::size_t j = 0; j < 2; ++j)
      for (std::size_t l = 0; l < 3; ++l) {
        ContactCellResult& c = t.cells[i][j][l];
        c.tolerance = std::ldexp(s.steps[j], -s.levels[l]);
        c.max_error = 0.5 * c.tolerance;
        c.contacts = s.drops;
        c.bisections = s.levels[l] + 0.5;
      }
  return t;
}

ContactTimeSettings small_contact() {
  ContactTimeSettings s;
  s.steps = {0.1, 0.01};
  s.levels = {4, 8, 12};
  s.drops = 5;
  return s;
}

TEST(PlaneReport, ContactConclusionsFollowTheTable) {
  const ContactTimeSettings s = small_contact();
  ContactTable t = planted(s);
  std::string md = contact_conclusions(s, t);
  EXPECT_TRUE(has(md, "`midpoint`: its largest error is 0.5 times the bisection tolerance")) << md;
  EXPECT_TRUE(has(md, "stays within the tolerance")) << md;
  EXPECT_TRUE(has(md, "`symplectic`: at k = 12 its error is")) << md;
  EXPECT_TRUE(has(md, "it follows the tolerance")) << md;
  EXPECT_TRUE(has(md, "exceed k by 0.5 to 0.5 in every complete cell: each extra level costs one more")) << md;
  // Midpoint over the tolerance at h = 0.01, k = 8; symplectic stuck at 0.4 h at the finest level.
  t.cells[0][1][1].max_error = 1.5 * t.cells[0][1][1].tolerance;
  for (std::size_t j = 0; j < 2; ++j) t.cells[1][j][2].max_error = 0.4 * s.steps[j];
  md = contact_conclusions(s, t);
  EXPECT_TRUE(has(md, "its largest error is 1.5 times the bisection tolerance (h = 0.01 s, k = 8), so the error "
                      "does not stay within"))
      << md;
  EXPECT_TRUE(has(md, "at k = 12 its error is 0.4 h to 0.4 h over the steps")) << md;
  EXPECT_TRUE(has(md, "it stops at the integrator's own error")) << md;
  // A failed cell and an incomplete one are left out and named, in the table too.
  t.error[0][0][2] = "case 9 threw: x";
  t.cells[1][0][0].first_missing = 2;
  t.cells[1][0][0].contacts = 4;
  md = contact_conclusions(s, t);
  EXPECT_TRUE(has(md, "Left out (failed or incomplete): midpoint h = 0.1 k = 12, symplectic h = 0.1 k = 4.")) << md;
  const std::string table = contact_table(s, t);
  EXPECT_TRUE(has(table, "failed: case 9 threw: x")) << table;
  EXPECT_TRUE(has(table, "failed: drop 2 made no contact within 10 s (4 of 5 did)")) << table;
  EXPECT_TRUE(contact_json(s, t)[2].contains("error"));
}

DropTable planted_drops() {
  DropTable t;
  for (double z0 : {0.5, 2.0}) {
    DropRow r;
    r.z0 = z0;
    r.t_exact = 1.0, r.t_core = 1.0;
    r.apex_exact = 0.25 * z0, r.apex_core = 0.25 * z0;
    r.bullet = true;
    r.t_rigid = 1.0 - 0.5 * 0.005, r.apex_rigid = 0.3 * z0;
    r.t_node = 1.0, r.node_margin = 0.001, r.apex_node = 0.001;
    r.node_not_modelled = {"per-particle elasticity: no restitution"};
    t.rows.push_back(r);
    t.error.push_back("");
  }
  return t;
}

TEST(PlaneReport, DropConclusionsFollowTheTable) {
  const DropSettings s;
  DropTable t = planted_drops();
  std::string md = drop_conclusions(s, t);
  EXPECT_TRUE(has(md, "Core: contact +0 to +0 steps")) << md;
  EXPECT_TRUE(has(md, "Bullet rigid sphere: contact -0.5 to -0.5 steps")) << md;
  EXPECT_TRUE(has(md, "apex +0.2 to +0.2 relative")) << md;
  EXPECT_TRUE(has(md, "it does not rebound")) << md;
  EXPECT_TRUE(has(md, "  - per-particle elasticity: no restitution")) << md;
  t.rows[1].apex_node = 0.3;
  md = drop_conclusions(s, t);
  EXPECT_TRUE(has(md, "it rebounds up to 0.299 m above its margin")) << md;
  t.rows[0].t_core = NAN;
  EXPECT_TRUE(has(drop_conclusions(s, t), "Core: contact missing for some height")) << drop_conclusions(s, t);
  t.error[1] = "case 30 threw: y";
  EXPECT_TRUE(has(drop_table(t, true), "| 2 | failed: case 30 threw: y |")) << drop_table(t, true);
  EXPECT_EQ(drop_data(t)[1]["error"], "case 30 threw: y");
  EXPECT_EQ(drop_data(t)[1]["z0"], 2.0);
}

}  // namespace
}  // namespace tecido::suites::plane
