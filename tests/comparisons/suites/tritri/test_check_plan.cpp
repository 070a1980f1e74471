// The tritri suite's checks (comparisons/suites/tritri/check_plan.*), declared from the family
// table, the engines and the tolerance file before anything runs: core on every family, the
// reference engines on random pairs, the seed's two tests and the referee reported only.
#include "comparisons/suites/tritri/check_plan.h"

#include "comparisons/io/input_error.h"

#include <gtest/gtest.h>

namespace tecido::suites::tritri {
namespace {

Tolerances tolerances() {
  return Tolerances(io::Json::parse(R"({"tritri":{"core_min_agreement":0.75,"fcl_min_agreement":0.5,
                                                  "ccd-gjk_min_agreement":0.25}})"),
                    "tol.json");
}

TEST(TritriCheckPlan, CoreEveryFamilyReferencesOnRandomSeedTestsReported) {
  const Tolerances tol = tolerances();
  const std::vector<std::string> engines = {"core", "core-rotation", "core-mt", "fcl", "ccd-gjk", "exact"};
  const std::vector<Check> c = declare_checks(families(), engines, "exact", tol).finish();
  std::vector<std::string> want;
  for (const Family& f : families()) want.push_back("tritri/core/agreement/" + f.name);
  want.push_back("tritri/fcl/agreement/random");
  want.push_back("tritri/ccd-gjk/agreement/random");
  ASSERT_EQ(c.size(), want.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    EXPECT_EQ(c[i].name, want[i]);
    EXPECT_FALSE(c[i].pass) << "nothing produced yet";
    EXPECT_EQ(c[i].reason, "not produced");
    EXPECT_EQ(c[i].hi, 1.0);
  }
  EXPECT_EQ(c.front().lo, 0.75);
  EXPECT_EQ(c.front().tolerance, "/tritri/core_min_agreement");
  EXPECT_EQ(c[c.size() - 2].lo, 0.5);
  EXPECT_EQ(c.back().lo, 0.25);
}

TEST(TritriCheckPlan, Scopes) {
  EXPECT_EQ(check_scope("core", "exact"), CheckScope::EveryFamily);
  EXPECT_EQ(check_scope("core-rotation", "exact"), CheckScope::Reported);
  EXPECT_EQ(check_scope("core-mt", "exact"), CheckScope::Reported);
  EXPECT_EQ(check_scope("exact", "exact"), CheckScope::Reported);
  EXPECT_EQ(check_scope("fcl", "exact"), CheckScope::RandomOnly);
  EXPECT_EQ(check_scope("my-engine", "exact"), CheckScope::RandomOnly) << "a new engine is checked on random pairs";
  const Family& random = families().front();
  const Family& coplanar = families().at(2);
  EXPECT_TRUE(is_checked(CheckScope::RandomOnly, random));
  EXPECT_FALSE(is_checked(CheckScope::RandomOnly, coplanar));
  EXPECT_TRUE(is_checked(CheckScope::EveryFamily, coplanar));
  EXPECT_FALSE(is_checked(CheckScope::Reported, random));
}

TEST(TritriCheckPlan, AnEngineWithoutABandIsBadInput) {
  EXPECT_THROW(declare_checks(families(), {"core", "my-engine"}, "exact", tolerances()), io::InputError);
}

TEST(TritriCheckPlan, TheBandsChangePassNotNames) {
  const Tolerances a = tolerances();
  const Tolerances b(io::Json::parse(R"({"tritri":{"core_min_agreement":2,"fcl_min_agreement":-1,
                                                   "ccd-gjk_min_agreement":1e300}})"),
                     "other.json");
  const std::vector<std::string> engines = {"core", "fcl", "ccd-gjk", "exact"};
  const auto ca = declare_checks(families(), engines, "exact", a).finish();
  const auto cb = declare_checks(families(), engines, "exact", b).finish();
  ASSERT_EQ(ca.size(), cb.size());
  for (std::size_t i = 0; i < ca.size(); ++i) EXPECT_EQ(ca[i].name, cb[i].name);
}

}  // namespace
}  // namespace tecido::suites::tritri
