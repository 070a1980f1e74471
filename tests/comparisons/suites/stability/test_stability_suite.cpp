// The stability suite (comparisons/suites/stability/stability_suite.*) cannot lie: a NaN or empty grid
// cell, an unstable run and a group that throws each fail the checks they feed, with the reason
// beside them, and no check disappears; the tolerance file changes pass or fail, never the work.
#include "comparisons/io/source_dir.h"
#include "tests/support/cli_runner.h"
#include "comparisons/suites/stability/stability_suite.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <stdexcept>

namespace tecido::suites::stability {
namespace {

/// Small settings: the whole sweep runs in well under a second, also under the sanitizers.
Settings small_suite() {
  Settings s = settings(true);
  s.periods = 50.0;
  s.stiffnesses = {1.0, 100.0};
  s.masses = {0.01, 1.0};
  s.growth_cs = {0.1, 1.0};
  s.horizons = {10.0, 30.0};
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

Tolerances file_tolerances() { return Tolerances::load(std::string(TECIDO_SOURCE_DIR) + "/data/tolerances.json"); }

struct Fixture {
  Tolerances tol = file_tolerances();
  SuiteContext ctx;
  Plan plan;
  std::vector<io::Json> results;
  explicit Fixture(std::vector<ExtremeGroup> groups = extreme_groups()) {
    ctx.tolerances = &tol;
    plan = make_plan(ctx, small_suite(), std::move(groups));
    for (std::size_t k = 0; k < case_count(plan.layout); ++k)
      results.push_back(run_case(plan.settings, plan.groups, plan.layout, k));
  }
  std::map<std::string, Check> checks(const std::vector<io::Json>& r) const {
    std::map<std::string, Check> out;
    for (const Check& c : assemble(plan, r).checks) out[c.name] = c;
    return out;
  }
};

std::vector<std::string> names(const SuiteResult& r) {
  std::vector<std::string> out;
  for (const Check& c : r.checks) out.push_back(c.name);
  return out;
}

TEST(StabilitySuite, SmallSettingsProduceEveryCheck) {
  const Fixture f;
  const SuiteResult r = assemble(f.plan, f.results);
  ASSERT_EQ(r.checks.size(), f.plan.checks.size());
  for (const Check& c : r.checks) EXPECT_TRUE(c.reason.empty()) << c.name << ": " << c.reason;
  EXPECT_TRUE(r.data.contains("max_step"));
  EXPECT_NE(r.markdown.find("settings.h"), std::string::npos);
}

TEST(StabilitySuite, ANaNGridCellFailsTheGridChecksNamingTheCell) {
  const Fixture f;
  std::vector<io::Json> r = f.results;
  // symplectic (kind 0), ks = 100 N/m (index 1), m = 0.01 kg (index 0)
  r[case_index(f.plan.layout, {CaseGroup::Grid, grid_index(f.plan.settings, {0, 1, 0})})]["h"] = "nan";
  const auto c = f.checks(r);
  for (const char* what : {"h_omega_ratio_min", "h_omega_ratio_max", "grid_spread"}) {
    const Check& x = c.at(std::string("stability/symplectic/") + what);
    EXPECT_FALSE(x.pass) << what;
    EXPECT_EQ(x.reason, "NaN at ks = 100 N/m, m = 0.01 kg") << what;
  }
  // The other integrator's checks keep their values.
  EXPECT_TRUE(c.at("stability/rk4/h_omega_ratio_min").reason.empty());
  EXPECT_EQ(c.size(), f.plan.checks.size());
}

TEST(StabilitySuite, AnEmptyGridCellFailsWithItsReason) {
  const Fixture f;
  std::vector<io::Json> r = f.results;
  io::Json& cell = r[case_index(f.plan.layout, {CaseGroup::Grid, grid_index(f.plan.settings, {1, 0, 1})})];
  cell["found"] = false;
  cell["h_unstable"] = 0.25;
  const Check x = f.checks(r).at("stability/rk4/h_omega_ratio_max");
  EXPECT_FALSE(x.pass);
  EXPECT_EQ(x.reason, "no stable step at ks = 1 N/m, m = 1 kg (unstable down to h = 0.25 s)");
  // A cell whose case threw names the cell and carries the exception's message.
  r = f.results;
  r[case_index(f.plan.layout, {CaseGroup::Grid, 0})] = io::Json{{"error", "case 5 threw: planted"}};
  const Check y = f.checks(r).at("stability/symplectic/grid_spread");
  EXPECT_EQ(y.reason, "ks = 1 N/m, m = 0.01 kg: case 5 threw: planted");
}

TEST(StabilitySuite, AnUnstableGrowthRunFailsItsCheck) {
  const Fixture f;
  std::vector<io::Json> r = f.results;
  r[case_index(f.plan.layout, {CaseGroup::Growth, growth_index(f.plan.settings, {1, 1, 0, 0})})] =
      io::Json{{"growth_per_step", "inf"}, {"finite", false}, {"unstable_step", 12}};
  const auto c = f.checks(r);
  EXPECT_EQ(c.at("stability/midpoint/growth_rel_error").reason, "unstable at step 12 (c = 1, ks = 1 N/m, m = 0.01 kg)");
  EXPECT_TRUE(c.at("stability/euler/growth_rel_error").reason.empty());
}

TEST(StabilitySuite, AGroupThatThrowsFailsItsChecksWithTheMessage) {
  const Fixture f;
  std::vector<io::Json> r = f.results;
  r[case_index(f.plan.layout, {CaseGroup::Extremes, 3})] = io::Json{{"error", "case 3 threw: planted"}};  // resting
  const SuiteResult res = assemble(f.plan, r);
  EXPECT_EQ(names(res), names(assemble(f.plan, f.results)));
  for (const Check& c : res.checks) {
    if (c.name.rfind("stability/extremes/rest_", 0) == 0) {
      EXPECT_FALSE(c.pass);
      EXPECT_EQ(c.reason, "resting contact group: case 3 threw: planted");
    } else {
      EXPECT_TRUE(c.reason.empty()) << c.name << ": " << c.reason;
    }
  }
  EXPECT_NE(res.markdown.find("**Resting contact.** No result"), std::string::npos);
}

TEST(StabilitySuite, AThrowingGroupFunctionThroughTheSweep) {
  std::vector<ExtremeGroup> groups = extreme_groups();
  groups[1].run = [](const Settings&) -> ExtremeResult { throw std::runtime_error("planted"); };  // mass ratio
  const Tolerances tol = file_tolerances();
  SuiteContext ctx;
  ctx.tolerances = &tol;
  ctx.threads = 2;
  const Sweep sweep = stability_sweep_for(ctx, small_suite(), groups);
  std::vector<std::size_t> all(sweep.cases);
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
  const SuiteResult res = sweep.assemble(run_sweep_cases(sweep, all, 2, "t", false));
  const Plan plan = make_plan(ctx, small_suite(), groups);
  const std::size_t k = case_index(plan.layout, {CaseGroup::Extremes, 1});
  int failed = 0;
  for (const Check& c : res.checks) {
    if (c.name.rfind("stability/extremes/mass_ratio_", 0) != 0) continue;
    ++failed;
    EXPECT_FALSE(c.pass);
    EXPECT_EQ(c.reason, "mass ratio group: case " + std::to_string(k) + " threw: planted");
  }
  EXPECT_EQ(failed, 2);
  EXPECT_NE(res.markdown.find("| mass ratio | (the group itself) |"), std::string::npos);
}

TEST(StabilitySuite, ACheckWithoutAnOutcomeIsNotProduced) {
  // A group that forgets a check it declared: the check stays, failed "not produced".
  std::vector<ExtremeGroup> groups = extreme_groups();
  groups[4].run = [](const Settings&) { return ExtremeResult{}; };  // tunnelling, no outcome
  const Fixture f(groups);
  const Check c = f.checks(f.results).at("stability/extremes/tunnel_wrong_side_steps");
  EXPECT_FALSE(c.pass);
  EXPECT_EQ(c.reason, "not produced");
}

// ---- the command line -----------------------------------------------------------------------------

std::string q(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

/// report.json's data without the verdicts (words chosen against the bands).
nlohmann::json without_verdicts(nlohmann::json j) {
  if (j.is_object()) {
    j.erase("verdict");
    for (auto& v : j) v = without_verdicts(v);
  } else if (j.is_array()) {
    for (auto& v : j) v = without_verdicts(v);
  }
  return j;
}

TEST(SuiteCli, StabilityQuickPasses) {
  const auto dir = testing::temp_dir("suite-stability");
  const auto r = testing::run_cli("suite stability --quick --out " + q(dir));
  EXPECT_EQ(r.code, 0) << r.err << r.out;
  const auto j = nlohmann::json::parse(testing::slurp(dir / "report.json"));
  ASSERT_EQ(j["suites"].size(), 1u);
  EXPECT_EQ(j["suites"][0]["checks"].size(), 20u);
  for (const auto& c : j["suites"][0]["checks"]) EXPECT_TRUE(c["pass"].get<bool>()) << c.dump();
  std::filesystem::remove_all(dir);
}

// The acceptance test: a tolerance file whose every /stability number is changed (times 1.37,
// so ratio_lo = 1.30 cannot hold), with the old run parameters put back at their pathological value
// (periods and amplitude_bound 1, which used to make the suite run for more than 10 minutes), does
// the same work (the same measurements, bit for bit), reports the same checks and exits 1.
TEST(SuiteCli, StabilityToleranceFileChangesPassFailNeverTheWork) {
  const auto dir = testing::temp_dir("suite-stability-tol");
  auto doc = nlohmann::json::parse(testing::slurp(std::string(TECIDO_SOURCE_DIR) + "/data/tolerances.json"));
  for (auto& v : doc["stability"])
    if (v.is_number()) v = v.get<double>() * 1.37;
  doc["stability"]["periods"] = 1;
  doc["stability"]["amplitude_bound"] = 1;
  testing::write_text(dir / "tol.json", doc.dump(1));
  const auto normal = testing::run_cli("suite stability --quick --threads 2 --out " + q(dir / "normal"));
  const auto changed =
      testing::run_cli("suite stability --quick --threads 2 --tolerances " + q(dir / "tol.json") + " --out " + q(dir / "changed"));
  ASSERT_EQ(normal.code, 0) << normal.err;
  EXPECT_EQ(changed.code, 1) << changed.err;
  const auto a = nlohmann::json::parse(testing::slurp(dir / "normal" / "report.json"))["suites"][0];
  const auto b = nlohmann::json::parse(testing::slurp(dir / "changed" / "report.json"))["suites"][0];
  ASSERT_EQ(a["checks"].size(), b["checks"].size());
  int failed = 0;
  for (std::size_t i = 0; i < a["checks"].size(); ++i) {
    EXPECT_EQ(a["checks"][i]["name"], b["checks"][i]["name"]);
    EXPECT_EQ(a["checks"][i]["value"], b["checks"][i]["value"]) << a["checks"][i]["name"];
    failed += b["checks"][i]["pass"].get<bool>() ? 0 : 1;
  }
  EXPECT_GT(failed, 0);
  EXPECT_EQ(without_verdicts(a["data"]), without_verdicts(b["data"]));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido::suites::stability
