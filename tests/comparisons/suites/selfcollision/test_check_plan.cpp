// The selfcollision suite's checks (comparisons/suites/selfcollision/check_plan.*): declared for
// every engine but the truth on every source before anything runs, then set from a source's
// score or failed with the reason: a case that threw, unanswered frames, a vacuous recall.
#include "comparisons/suites/selfcollision/check_plan.h"

#include "comparisons/io/input_error.h"

#include <gtest/gtest.h>

namespace tecido::suites::selfcollision {
namespace {

Tolerances tolerances() {
  return Tolerances(io::Json::parse(R"({"selfcollision":{"core_min":0.5,"fcl_min":0.25}})"), "tol.json");
}

const std::vector<FrameSource> kSources = {{"one", "first", nullptr}, {"two", "second", nullptr}};

TEST(SelfcollisionCheckPlan, PrecisionAndRecallOfEveryEngineButTheTruthOnEverySource) {
  const std::vector<Check> c = declare_checks(kSources, {"core", "fcl", "exact"}, "exact", tolerances()).finish();
  const std::vector<std::string> want = {
      "selfcollision/core/one/precision", "selfcollision/core/one/recall", "selfcollision/core/two/precision",
      "selfcollision/core/two/recall",    "selfcollision/fcl/one/precision", "selfcollision/fcl/one/recall",
      "selfcollision/fcl/two/precision",  "selfcollision/fcl/two/recall"};
  ASSERT_EQ(c.size(), want.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    EXPECT_EQ(c[i].name, want[i]);
    EXPECT_EQ(c[i].reason, "not produced");
    EXPECT_EQ(c[i].lo, i < 4 ? 0.5 : 0.25);
    EXPECT_EQ(c[i].hi, 1.0);
  }
  EXPECT_THROW(declare_checks(kSources, {"core", "mine", "exact"}, "exact", tolerances()), io::InputError);
}

EngineScore score(const std::string& engine, long answered, PairAgreement p) {
  EngineScore e;
  e.engine = engine;
  e.answered = answered;
  e.pairs = p;
  return e;
}

TEST(SelfcollisionCheckPlan, ScoresSetValuesOrFailWithAReason) {
  CheckList checks = declare_checks(kSources, {"core", "fcl", "exact"}, "exact", tolerances());
  SourceScore one;
  one.frames = 4;
  one.true_pairs = 3;
  // core: 4 reported, 2 true, 1 missed -> precision 0.5, recall 2/3; fcl left a frame unanswered.
  one.engines = {score("core", 4, {4, 2, 2, 1}), score("fcl", 3, {3, 3, 0, 0}), score("exact", 4, {3, 3, 0, 0})};
  record_checks(checks, "one", {"core", "fcl", "exact"}, one);
  SourceScore two;
  two.error = "case 1 threw: no scene";
  record_checks(checks, "two", {"core", "fcl", "exact"}, two);
  const std::vector<Check> c = checks.finish();
  ASSERT_EQ(c.size(), 8u);
  EXPECT_DOUBLE_EQ(c[0].value, 0.5);
  EXPECT_TRUE(c[0].pass);
  EXPECT_DOUBLE_EQ(c[1].value, 2.0 / 3.0);
  for (int i : {2, 3, 6, 7}) EXPECT_EQ(c[i].reason, "case 1 threw: no scene") << c[i].name;
  for (int i : {4, 5}) EXPECT_EQ(c[i].reason, "1 of 4 frames unanswered") << c[i].name;
  for (const Check& k : c) {
    if (k.name.find("/two/") != std::string::npos || k.name.find("fcl") != std::string::npos) {
      EXPECT_FALSE(k.pass) << k.name;
    }
  }

  CheckList vacuous = declare_checks({kSources[0]}, {"core", "exact"}, "exact", tolerances());
  SourceScore none;
  none.frames = 2;
  none.engines = {score("core", 2, {}), score("exact", 2, {})};
  record_checks(vacuous, "one", {"core", "exact"}, none);
  const std::vector<Check> v = vacuous.finish();
  EXPECT_TRUE(v[0].pass) << "nothing reported, nothing true: precision 1";
  EXPECT_FALSE(v[1].pass);
  EXPECT_EQ(v[1].reason, "no true pair in the frames: recall is vacuous");
}

}  // namespace
}  // namespace tecido::suites::selfcollision
