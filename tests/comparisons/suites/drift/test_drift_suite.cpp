// The drift suite's case table and declared checks (comparisons/suites/drift/drift_suite.h), and its
// assembly on planted case results: a case that threw, an unstable run and a NaN each fail their
// checks with a reason and never drop one; the check names depend on the settings only.
#include "comparisons/io/source_dir.h"
#include "comparisons/suites/drift/drift_suite.h"

#include "comparisons/suites/drift/invariants.h"
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>

#include <set>

namespace tecido::suites {
namespace {

/// The drift section of data/tolerances.json with every number replaced by f(number).
Tolerances drift_tolerances(double (*f)(double)) {
  io::Json doc = io::Json::parse(testing::slurp(std::string(TECIDO_SOURCE_DIR) + "/data/tolerances.json"));
  for (auto& [key, value] : doc["drift"].items())
    if (value.is_number()) value = f(value.get<double>());
  return Tolerances(doc, "planted");
}

double same(double x) { return x; }
double changed(double x) { return -3.0 * x - 1.0; }

std::vector<std::string> names(const std::vector<Check>& checks) {
  std::vector<std::string> out;
  for (const Check& c : checks) out.push_back(c.name);
  return out;
}

constexpr std::size_t kBulletCases = 4, kBulletChecks = 8;

TEST(DriftSuite, CaseTableIsScenesTimesIntegratorsThenTheBulletGroups) {
  const auto cases = drift::drift_cases(drift::settings(true), 7);
  ASSERT_EQ(cases.size(), 8 + kBulletCases);
  EXPECT_EQ(cases[0].label, "two-body-3d/euler");
  EXPECT_EQ(cases[1].label, "two-body-3d/symplectic");
  EXPECT_EQ(cases[3].label, "two-body-3d/rk4");
  EXPECT_EQ(cases[4].label, "free-cloth/euler");
  EXPECT_EQ(cases[8].label, "twin");
  EXPECT_EQ(cases[9].label, "falling");
  EXPECT_EQ(cases[10].label, "classic");
  EXPECT_EQ(cases[11].label, "wind");
}

TEST(DriftSuite, ChecksAreDeclaredFromSettingsWithBandsFromTheFile) {
  const drift::Settings s = drift::settings(true);
  const CheckList a = drift::declare_drift_checks(s, 7, drift_tolerances(&same));
  const CheckList b = drift::declare_drift_checks(s, 7, drift_tolerances(&changed));
  // 2 scenes x (4 x (momentum, angular momentum) + 2 symplectic energy + 1 euler energy).
  ASSERT_EQ(a.size(), 2 * (8 + 3) + kBulletChecks);
  const auto ca = a.finish(), cb = b.finish();
  EXPECT_EQ(names(ca), names(cb));
  for (const Check& c : ca) {
    EXPECT_FALSE(c.tolerance.empty()) << c.name << ": every band comes from the file";
    EXPECT_EQ(c.reason, "not produced") << c.name;
  }
  const auto find = [&](const std::vector<Check>& cs, const std::string& n) {
    for (const Check& c : cs)
      if (c.name == n) return c;
    ADD_FAILURE() << n;
    return Check{};
  };
  EXPECT_EQ(find(ca, "drift/two-body-3d/rk4/angular_momentum").hi, 1e-12);
  EXPECT_EQ(find(cb, "drift/two-body-3d/rk4/angular_momentum").hi, changed(1e-12));
  // Bands scaled by the step: the file holds the number of steps.
  const Check ct = find(ca, "drift/falling/twin_contact_time_error");
  EXPECT_DOUBLE_EQ(ct.hi, 2.0 * s.twin_dt);
  EXPECT_EQ(ct.tolerance, "/drift/twin_contact_time_error_steps");
  const Check cr = find(ca, "drift/classic/load_x2/sag_ratio");
  EXPECT_DOUBLE_EQ(cr.lo, 0.5 - 0.02);
  EXPECT_DOUBLE_EQ(cr.hi, 0.5 + 0.02);
}

TEST(DriftSuite, PlantedFailuresFailTheirChecksWithAReason) {
  const auto dir = testing::temp_dir("drift-planted");
  const Tolerances tol = drift_tolerances(&same);
  SuiteContext ctx;
  ctx.quick = true;
  ctx.seed = 7;
  ctx.tolerances = &tol;
  ctx.out_dir = dir.string();
  const Sweep sweep = drift_sweep(ctx);
  std::vector<io::Json> results(sweep.cases, io::Json{{"error", "case threw: planted"}});
  drift::InvariantRun unstable;
  unstable.steps = 100;
  unstable.unstable_at_step = 7;
  results[1] = drift::invariant_json(unstable);  // two-body-3d/symplectic
  drift::InvariantRun nan_run;
  nan_run.momentum_error = std::nan("");
  results[6] = drift::invariant_json(nan_run);  // free-cloth/midpoint
  const SuiteResult r = sweep.assemble(results);
  const CheckList declared = drift::declare_drift_checks(drift::settings(true), 7, tol);
  EXPECT_EQ(names(r.checks), names(declared.finish()));
  for (const Check& c : r.checks) {
    if (c.name == "drift/free-cloth/midpoint/angular_momentum") {
      EXPECT_TRUE(c.pass) << "a planted 0 is a value";
      continue;
    }
    EXPECT_FALSE(c.pass) << c.name;
    if (c.name.rfind("drift/two-body-3d/symplectic/", 0) == 0) {
      EXPECT_EQ(c.reason, "unstable at step 7") << c.name;
    } else if (c.name == "drift/free-cloth/midpoint/momentum") {
      EXPECT_EQ(c.reason, "value is NaN");
    } else {
      EXPECT_EQ(c.reason, "case threw: planted") << c.name;
    }
  }
  EXPECT_NE(r.markdown.find("unstable at step 7"), std::string::npos);
  std::filesystem::remove_all(dir);
}

// The whole suite through the CLI with a tolerance file whose every drift number is changed: the
// same checks are reported, the same work is done (the report's measured data are identical: the
// drift suite measures no wall time), and the exit code says a check failed.
TEST(DriftSuiteCli, EveryBandChangedGivesTheSameChecksTheSameWorkAndExitOne) {
  const auto dir = testing::temp_dir("drift-perturbed");
  io::Json doc = io::Json::parse(testing::slurp(std::string(TECIDO_SOURCE_DIR) + "/data/tolerances.json"));
  int changed_numbers = 0;
  for (auto& [key, value] : doc["drift"].items())
    if (value.is_number()) value = changed(value.get<double>()), ++changed_numbers;
  EXPECT_GE(changed_numbers, 10);
  testing::write_text(dir / "tolerances.json", doc.dump(2));
  const auto normal = testing::run_cli("suite drift --quick --out '" + (dir / "a").string() + "'");
  const auto perturbed = testing::run_cli("suite drift --quick --tolerances '" + (dir / "tolerances.json").string() +
                                          "' --out '" + (dir / "b").string() + "'");
  EXPECT_EQ(normal.code, 0) << normal.err;
  EXPECT_EQ(perturbed.code, 1) << perturbed.err;
  const auto a = io::Json::parse(testing::slurp(dir / "a" / "report.json"))["suites"][0];
  const auto b = io::Json::parse(testing::slurp(dir / "b" / "report.json"))["suites"][0];
  ASSERT_EQ(a["checks"].size(), b["checks"].size());
  for (std::size_t k = 0; k < a["checks"].size(); ++k) {
    EXPECT_EQ(a["checks"][k]["name"], b["checks"][k]["name"]);
    EXPECT_EQ(a["checks"][k]["value"], b["checks"][k]["value"]) << a["checks"][k]["name"];
  }
  EXPECT_EQ(a["data"], b["data"]);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido::suites
