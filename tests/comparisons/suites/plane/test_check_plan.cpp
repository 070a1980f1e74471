// The plane suite's declared checks (comparisons/suites/plane/check_plan.*): which engines are
// checked on which groups, the names (independent of the tolerance numbers), the bands (read from
// the tolerance file, the Bullet band in steps times the drop's step), and a missing band named.
#include "comparisons/io/source_dir.h"
#include "comparisons/suites/plane/check_plan.h"

#include "comparisons/io/input_error.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

namespace tecido::suites::plane {
namespace {

Tolerances file_tolerances() { return Tolerances::load(std::string(TECIDO_SOURCE_DIR) + "/data/tolerances.json"); }

/// The tolerance file with every number of its /plane section multiplied by `f`, and bands for "mine".
Tolerances scaled(double f) {
  io::Json doc = file_tolerances().doc();
  for (auto it = doc["plane"].begin(); it != doc["plane"].end(); ++it)
    if (it.key()[0] != '_') it.value() = it.value().get<double>() * f;
  for (const char* g : {"random", "border", "exact-geometry", "grazing", "far"})
    doc["plane"][std::string("mine_agreement_") + g] = 0.5 * f;
  doc["plane"]["mine_t_error_near"] = 0.1 * f;
  doc["plane"]["mine_t_error_far"] = 0.2 * f;
  return Tolerances(doc, "scaled.json");
}

std::vector<std::string> names(const CheckList& c) {
  std::vector<std::string> out;
  for (const Check& x : c.finish()) out.push_back(x.name);
  return out;
}

const std::vector<std::string> kEngines = {"core", "core-seed", "fcl", "mine"};

TEST(PlaneCheckPlan, EveryCategoryInExactlyOneGroup) {
  std::set<std::string> in_groups;
  for (const CategoryGroup& g : category_groups())
    for (const std::string& m : g.categories) EXPECT_TRUE(in_groups.insert(m).second) << m;
  for (const Category& c : categories()) {
    EXPECT_EQ(in_groups.count(c.name), 1u) << c.name;
    ASSERT_NE(group_of(c.name), nullptr);
  }
  EXPECT_EQ(in_groups.size(), categories().size());
  EXPECT_EQ(group_of("nothing"), nullptr);
}

TEST(PlaneCheckPlan, ScopesOfTheEngines) {
  EXPECT_EQ(check_scope("core", "exact"), CheckScope::Exact);
  EXPECT_EQ(check_scope("core-seed", "exact"), CheckScope::Reported);
  EXPECT_EQ(check_scope("core-other", "exact"), CheckScope::Reported);
  EXPECT_EQ(check_scope("exact", "exact"), CheckScope::Reported);
  EXPECT_EQ(check_scope("fcl", "exact"), CheckScope::Reference);
}

TEST(PlaneCheckPlan, DeclaredNamesInOrder) {
  const Settings s = settings(false);
  const auto got = names(declare_checks(s, kEngines, "exact", true, scaled(1.0)));
  std::vector<std::string> want;
  for (const char* e : {"core", "fcl", "mine"})  // core-seed: reported, not checked
    for (const char* g : {"random", "border", "exact-geometry", "grazing", "far"}) {
      want.push_back(std::string("plane/") + e + "/agreement/" + g);
      if (std::string(g) != "grazing") want.push_back(std::string("plane/") + e + "/t_error/" + g);
    }
  for (const char* h : {"0.1", "0.02", "0.005"}) want.push_back(std::string("plane/contact_time/midpoint/h=") + h);
  want.push_back("plane/drop/core_apex_rel_error");
  want.push_back("plane/drop/bullet_rigid_contact_time_error");
  EXPECT_EQ(got, want);
}

TEST(PlaneCheckPlan, NamesDependOnNeitherTheBandsNorQuick) {
  const auto a = names(declare_checks(settings(false), kEngines, "exact", true, scaled(1.0)));
  EXPECT_EQ(names(declare_checks(settings(false), kEngines, "exact", true, scaled(1.37))), a);
  EXPECT_EQ(names(declare_checks(settings(true), kEngines, "exact", true, scaled(0.01))), a);
}

TEST(PlaneCheckPlan, BandsComeFromTheToleranceFile) {
  const Tolerances tol = scaled(1.37);
  const Settings s = settings(true);
  std::map<std::string, Check> by_name;
  for (const Check& c : declare_checks(s, kEngines, "exact", true, tol).finish()) by_name[c.name] = c;
  const Check& core = by_name.at("plane/core/agreement/border");
  EXPECT_EQ(core.lo, tol.get("/plane/core_agreement_border"));
  EXPECT_EQ(core.hi, 1.0);
  EXPECT_EQ(core.tolerance, "/plane/core_agreement_border");
  EXPECT_EQ(by_name.at("plane/fcl/t_error/far").hi, tol.get("/plane/fcl_t_error_far"));
  EXPECT_EQ(by_name.at("plane/mine/t_error/exact-geometry").hi, tol.get("/plane/mine_t_error_near"));
  EXPECT_EQ(by_name.at("plane/contact_time/midpoint/h=0.02").hi, tol.get("/plane/contact_time_over_tolerance"));
  EXPECT_EQ(by_name.at("plane/drop/core_apex_rel_error").hi, tol.get("/plane/drop_core_apex_rel"));
  const Check& bullet = by_name.at("plane/drop/bullet_rigid_contact_time_error");
  EXPECT_DOUBLE_EQ(bullet.hi, tol.get("/plane/drop_bullet_contact_time_error_steps") * s.drop.dt);
  EXPECT_EQ(bullet.tolerance, "/plane/drop_bullet_contact_time_error_steps");
  for (const auto& [name, c] : by_name) {
    EXPECT_FALSE(c.pass) << name;  // nothing measured yet
    EXPECT_FALSE(c.note.empty()) << name;
  }
}

TEST(PlaneCheckPlan, WithoutRefereeOrBulletFewerChecks) {
  const auto got = names(declare_checks(settings(true), kEngines, "", false, scaled(1.0)));
  EXPECT_EQ(got, (std::vector<std::string>{"plane/contact_time/midpoint/h=0.1", "plane/contact_time/midpoint/h=0.02",
                                           "plane/contact_time/midpoint/h=0.005", "plane/drop/core_apex_rel_error"}));
}

TEST(PlaneCheckPlan, EveryIntegratorExactForConstantAccelerationIsChecked) {
  Settings s = settings(true);
  s.contact_time.integrators = {IntegratorKind::Euler, IntegratorKind::RK4};
  s.contact_time.steps = {0.05};
  const auto got = names(declare_checks(s, {}, "", false, scaled(1.0)));
  EXPECT_EQ(got, (std::vector<std::string>{"plane/contact_time/rk4/h=0.05", "plane/drop/core_apex_rel_error"}));
}

TEST(PlaneCheckPlan, AMissingBandIsNamed) {
  try {
    declare_checks(settings(true), {"core", "newcomer"}, "exact", true, file_tolerances());
    FAIL() << "no error";
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/plane/newcomer_agreement_random"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tecido::suites::plane
