// The stability suite's extremes (comparisons/suites/stability/extremes.* and one file per group):
// a group's result survives JSON, a judged verdict follows its band, and every group produces
// exactly the checks it declares, with hand-known values where the physics fixes them.
#include "comparisons/suites/stability/cases.h"
#include "comparisons/suites/stability/extremes.h"
#include "comparisons/suites/stability/near_zero.h"
#include "comparisons/suites/stability/tunnelling.h"
#include "comparisons/io/input_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>

namespace tecido::suites::stability {
namespace {

/// Small settings: every group runs in a fraction of a second, also under the sanitizers.
Settings small() {
  Settings s = settings(true);
  s.periods = 50.0;
  s.offset.offsets = {1e7};
  s.offset.periods = 1.0;
  s.offset.drop_steps = 200;
  s.near_zero.periods = 1.0;
  s.near_zero.coincident_steps = 10;
  s.resting.steps = 200;
  s.tunnelling.speeds = {1000.0};
  s.tunnelling.dts = {0.1, 10.0};
  return s;
}

TEST(Extremes, AResultRoundTripsThroughJson) {
  ExtremeResult r;
  r.rows.push_back({"g", "case a", "measured a", "ok", {}});
  r.rows.push_back({"g", "case b", "measured b", "", ExtremeRow::Judge{"ratio", {1.0, std::nan("")}, "fine", "off"}});
  r.set("stability/extremes/x", 0.1 + 0.2);
  r.fail("stability/extremes/y", "unstable at step 12 (euler)");
  r.data["g"] = {{"k", 1}};
  const ExtremeResult b = result_from_json(io::Json::parse(result_json(r).dump()));
  ASSERT_EQ(b.rows.size(), 2u);
  EXPECT_EQ(b.rows[0].label, "case a");
  EXPECT_FALSE(b.rows[0].judge.has_value());
  ASSERT_TRUE(b.rows[1].judge.has_value());
  EXPECT_TRUE(std::isnan(b.rows[1].judge->values[1]));
  ASSERT_EQ(b.outcomes.size(), 2u);
  EXPECT_EQ(b.outcomes[0].value, 0.1 + 0.2);
  EXPECT_EQ(b.outcomes[1].reason, "unstable at step 12 (euler)");
  EXPECT_EQ(b.data, r.data);
}

TEST(Extremes, AJudgedVerdictFollowsItsBand) {
  const VerdictBands bands = {{"ratio", Band{0.95, 1.02, "/s/lo /s/hi"}}};
  ExtremeRow row{"g", "c", "m", "", ExtremeRow::Judge{"ratio", {0.99, 1.01}, "ok", "broke"}};
  EXPECT_EQ(verdict(row, bands), "ok");
  row.judge->values.push_back(1.03);
  EXPECT_EQ(verdict(row, bands), "broke");
  row.judge->values = {std::nan("")};
  EXPECT_EQ(verdict(row, bands), "broke");
  row.judge->band = "nonexistent";
  EXPECT_THROW(verdict(row, bands), std::logic_error);
  const ExtremeRow settled{"g", "c", "m", "broke: non-finite", {}};
  EXPECT_EQ(verdict(settled, bands), "broke: non-finite");
}

TEST(Extremes, VerdictBandsComeFromTheToleranceFile) {
  const Tolerances tol(
      io::Json::parse(R"({"stability":{"ratio_lo":0.9,"ratio_hi":1.1,"rest_max_jitter":2e-12,"offset_degraded_fraction":0.01}})"),
      "tol.json");
  const VerdictBands b = verdict_bands(tol);
  EXPECT_EQ(b.at("ratio").lo, 0.9);
  EXPECT_EQ(b.at("ratio").hi, 1.1);
  EXPECT_EQ(b.at("rest_jitter").hi, 2e-12);
  EXPECT_EQ(b.at("offset_degraded").hi, 0.01);
  const Tolerances missing(io::Json::parse(R"({"stability":{"ratio_lo":0.9,"ratio_hi":1.1}})"), "tol.json");
  EXPECT_THROW(verdict_bands(missing), io::InputError);
}

TEST(Extremes, EveryGroupProducesExactlyTheChecksItDeclares) {
  const Settings s = small();
  for (const ExtremeGroup& g : extreme_groups()) {
    std::set<std::string> declared, produced;
    for (const CheckSpec& c : g.checks(s)) declared.insert(c.name);
    const ExtremeResult r = g.run(s);
    for (const Outcome& o : r.outcomes) {
      EXPECT_TRUE(produced.insert(o.check).second) << g.name << ": " << o.check << " twice";
      EXPECT_TRUE(o.reason.empty()) << g.name << ": " << o.check << ": " << o.reason;
    }
    EXPECT_EQ(produced, declared) << g.name;
    EXPECT_FALSE(r.rows.empty()) << g.name;
    for (const ExtremeRow& row : r.rows) EXPECT_EQ(row.group, g.name);
  }
}

TEST(Extremes, NearZeroRestLengthsHandValues) {
  const Settings s = small();
  const ExtremeResult r = run_near_zero(s);
  // Coincident ends: the force is skipped, exactly 0; nothing is NaN.
  for (const Outcome& o : r.outcomes) EXPECT_EQ(o.value, 0.0) << o.check;
  // 3 rest lengths x 2 passes + 4 coincident + 2 separations.
  EXPECT_EQ(r.data["near_zero"]["runs"].get<long long>(), 12);
  // At 1e-200 m apart |d|^2 rounds to 0 and the force is skipped; at 1e-160 m it pushes apart.
  ASSERT_EQ(r.rows.size(), 12u);
  EXPECT_NE(r.rows[10].verdict.find("direction kept"), std::string::npos) << r.rows[10].verdict;
  EXPECT_NE(r.rows[11].verdict.find("force skipped"), std::string::npos) << r.rows[11].verdict;
}

TEST(Extremes, TunnellingCountsNoWrongSideStep) {
  const ExtremeResult r = run_tunnelling(small());
  ASSERT_EQ(r.outcomes.size(), 1u);
  EXPECT_EQ(r.outcomes[0].value, 0.0);
  // 1 speed x 2 steps x 4 integrators.
  EXPECT_EQ(r.data["tunnelling"]["runs"].get<long long>(), 8);
  EXPECT_EQ(r.data["tunnelling"]["max_dt"].get<double>(), 10.0);
  EXPECT_EQ(tunnelling_checks(small())[0].note, "steps ending below a thin plane, any dt up to 10 s, any integrator");
}

}  // namespace
}  // namespace tecido::suites::stability
