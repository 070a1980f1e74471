// The tradeoff suite's declared checks (comparisons/suites/tradeoff/tradeoff_suite.h), its assembly
// on planted case results (a case that threw, a failed reference, an empty front: every check
// stays, failed with a reason), the prose derived from planted tables (findings.h), and the whole
// suite through the CLI with every band changed.
#include "comparisons/io/source_dir.h"
#include "comparisons/suites/tradeoff/tradeoff_suite.h"

#include "comparisons/suites/tradeoff/findings.h"
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>

namespace tecido::suites {
namespace {

double changed(double x) { return -3.0 * x - 1.0; }

Tolerances tradeoff_tolerances(bool perturb) {
  io::Json doc = io::Json::parse(testing::slurp(std::string(TECIDO_SOURCE_DIR) + "/data/tolerances.json"));
  if (perturb)
    for (auto& [key, value] : doc["tradeoff"].items())
      if (value.is_number()) value = changed(value.get<double>());
  return Tolerances(doc, "planted");
}

std::vector<std::string> names(const std::vector<Check>& checks) {
  std::vector<std::string> out;
  for (const Check& c : checks) out.push_back(c.name);
  return out;
}

TEST(TradeoffSuite, ChecksAreDeclaredFromTheSettingsWithBandsFromTheFile) {
  const tradeoff::Settings s = tradeoff::settings(true);
  const auto engines = tradeoff::tradeoff_engines(s);
  const CheckList a = tradeoff::declare_tradeoff_checks(s, engines, tradeoff_tolerances(false));
  const CheckList b = tradeoff::declare_tradeoff_checks(s, engines, tradeoff_tolerances(true));
  EXPECT_EQ(names(a.finish()), names(b.finish()));
  EXPECT_EQ(a.size(), 2 * 5u);  // conditioning, reference error and order, front size, twin vs core
  for (const Check& c : a.finish()) EXPECT_FALSE(c.tolerance.empty()) << c.name;
  // front_size's upper end is the number of points run on the size (settings only).
  for (const Check& c : a.finish()) {
    if (c.name == "tradeoff/16/front_size") {
      std::size_t points = 0;
      for (const auto& e : engines)
        for (std::size_t j = 0; j < 5; ++j) points += tradeoff::skipped(e, 16, j) ? 0 : 1;
      EXPECT_EQ(c.lo, 1.0);
      EXPECT_EQ(c.hi, static_cast<double>(points));
    }
  }
}

TEST(TradeoffSuite, PlantedFailuresFailEveryDeclaredCheckWithAReason) {
  const auto dir = testing::temp_dir("tradeoff-planted");
  const Tolerances tol = tradeoff_tolerances(false);
  SuiteContext ctx;
  ctx.quick = true;
  ctx.seed = 3;
  ctx.tolerances = &tol;
  ctx.out_dir = dir.string();
  const Sweep sweep = tradeoff_sweep(ctx);
  const std::vector<io::Json> results(sweep.cases, io::Json{{"error", "case threw: planted"}});
  const SuiteResult r = sweep.assemble(results);
  const tradeoff::Settings s = tradeoff::settings(true);
  const CheckList declared = tradeoff::declare_tradeoff_checks(s, tradeoff::tradeoff_engines(s), tol);
  EXPECT_EQ(names(r.checks), names(declared.finish()));  // no front point: no per-point check
  for (const Check& c : r.checks) {
    EXPECT_FALSE(c.pass) << c.name;
    EXPECT_FALSE(c.reason.empty() && std::isfinite(c.value) && c.value >= c.lo) << c.name;
  }
  EXPECT_NE(r.markdown.find("(empty: no run counted)"), std::string::npos);
  std::filesystem::remove_all(dir);
}

// Prose from a planted table: the classic body's numbers and the verdict on sweeps follow the values.
TEST(TradeoffFindings, ClassicParagraphIsDerivedFromTheTable) {
  using namespace tradeoff;
  std::vector<TradeoffEngine> engines(4);
  engines[0].name = "core-symplectic";
  engines[1].name = "bullet-deformable";
  engines[2].name = "bullet-classic-it1";
  engines[3].name = "bullet-classic-it4";
  SizeAnalysis a;
  a.n = 16;
  a.swept = {0.5, 0.25};
  auto pt = [](std::size_t e, std::size_t j, double err) {
    Point p;
    p.engine = e;
    p.step = j;
    p.h = j ? 0.25 : 0.5;
    p.error = err;
    p.cost = 1.0;
    return p;
  };
  a.points = {pt(2, 0, 0.04), pt(2, 1, 0.02), pt(3, 0, 0.05), pt(3, 1, 0.021)};
  const std::string md = bullet_findings({a}, engines, Settings{});
  EXPECT_NE(md.find("it is 0.04 to 0.05 m at h0 and 0.02 to 0.021 m at 2^-2"), std::string::npos) << md;
  EXPECT_NE(md.find("differ by at most 25 %"), std::string::npos) << md;
  EXPECT_EQ(md.find("hardly matters"), std::string::npos) << md;  // 25 % is not "hardly"
  a.points[2].error = 0.041;
  EXPECT_NE(bullet_findings({a}, engines, Settings{}).find("hardly matters"), std::string::npos);
}

// The whole suite through the CLI with a tolerance file whose every tradeoff number is changed:
// the same checks (the per-front-point ones excepted: the front follows the timings), the same
// work (every run's engine, step, status and error identical), and exit 1. Two quick runs of the
// suite: skipped under AddressSanitizer, where each takes minutes (as SuiteShard.TradeoffMerge...).
TEST(TradeoffSuiteCli, EveryBandChangedGivesTheSameChecksTheSameWorkAndExitOne) {
#ifdef TECIDO_SANITIZED
  GTEST_SKIP() << "too slow under AddressSanitizer";
#endif
  const auto dir = testing::temp_dir("tradeoff-perturbed");
  io::Json doc = io::Json::parse(testing::slurp(std::string(TECIDO_SOURCE_DIR) + "/data/tolerances.json"));
  int changed_numbers = 0;
  for (auto& [key, value] : doc["tradeoff"].items())
    if (value.is_number()) value = changed(value.get<double>()), ++changed_numbers;
  EXPECT_GE(changed_numbers, 6);
  testing::write_text(dir / "tolerances.json", doc.dump(2));
  const auto normal = testing::run_cli("suite tradeoff --quick --out '" + (dir / "a").string() + "'");
  const auto perturbed = testing::run_cli("suite tradeoff --quick --tolerances '" + (dir / "tolerances.json").string() +
                                          "' --out '" + (dir / "b").string() + "'");
  EXPECT_EQ(normal.code, 0) << normal.err;
  EXPECT_EQ(perturbed.code, 1) << perturbed.err;
  const auto a = io::Json::parse(testing::slurp(dir / "a" / "report.json"))["suites"][0];
  const auto b = io::Json::parse(testing::slurp(dir / "b" / "report.json"))["suites"][0];
  auto declared = [](const io::Json& suite) {
    std::vector<std::string> out;
    for (const auto& c : suite["checks"])
      if (c["name"].get<std::string>().find("/front/") == std::string::npos) out.push_back(c["name"]);
    return out;
  };
  EXPECT_EQ(declared(a), declared(b));
  for (const char* size : {"cloth16", "cloth32"}) {
    const auto &ra = a["data"][size]["runs"], &rb = b["data"][size]["runs"];
    ASSERT_EQ(ra.size(), rb.size()) << size;
    for (std::size_t k = 0; k < ra.size(); ++k)
      for (const char* key : {"engine", "h", "status", "error", "counted"}) EXPECT_EQ(ra[k][key], rb[k][key]) << size << " " << k;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido::suites
