// Suite statistics on planted inputs with known answers, and the report round trip.
#include "tests/support/cli_runner.h"
#include "comparisons/suites/order/order_fit.h"
#include "comparisons/suites/order/order_suite.h"
#include "comparisons/suites/report.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace tecido::suites {
namespace {

TEST(OrderFit, RecoversAPlantedOrderAndFindsTheRange) {
  // e = 3 h^2.5 in the middle, blown up (pre-asymptotic / unstable) at the two largest h and
  // flat at the round-off level 1e-13 at the smallest.
  std::vector<double> h, e;
  for (int k = 0; k < 17; ++k) {
    const double hk = 0.5 / std::pow(2.0, k);
    h.push_back(hk);
    double ek = 3.0 * std::pow(hk, 2.5);
    if (k == 0) ek = 10.0;
    if (k == 1) ek = std::numeric_limits<double>::infinity();
    ek = std::max(ek, 1e-13 * (1.0 + 0.3 * (k % 3)));
    e.push_back(ek);
  }
  const OrderFit f = fit_order(h, e, 1e-11, 0.02);
  ASSERT_GE(f.first, 0);
  EXPECT_NEAR(f.slope, 2.5, 1e-9);
  EXPECT_EQ(f.first, 2);
  EXPECT_GT(f.roundoff_below_h, 0.0);
  EXPECT_EQ(f.unstable_above_h, h[0]);  // the largest excluded step
  for (int k = f.first; k <= f.last; ++k) EXPECT_GT(e[k], 1e-11);
}

TEST(OrderFit, NoRangeWhenOrdersNeverSettle) {
  std::vector<double> h, e;
  for (int k = 0; k < 10; ++k) {
    h.push_back(1.0 / std::pow(2.0, k));
    e.push_back(1e-3 * std::pow(h.back(), (k % 2) ? 1.0 : 3.0));  // alternating: no stable order
  }
  const OrderFit f = fit_order(h, e, 1e-14, 1.0);
  EXPECT_EQ(f.first, -1);
  EXPECT_TRUE(std::isnan(f.slope));
}

TEST(Checks, BandsAndNaN) {
  EXPECT_TRUE(make_check("a", 1.0, 0.85, 1.15).pass);
  EXPECT_FALSE(make_check("a", 1.2, 0.85, 1.15).pass);
  EXPECT_FALSE(make_check("a", std::nan(""), -1e300, 1e300).pass);
  EXPECT_NEAR(check_margin(make_check("a", 1.0, 0.5, 1.5)), 0.5, 1e-15);
  EXPECT_LT(check_margin(make_check("a", 2.0, 0.5, 1.5)), 0.0);
}

TEST(Report, RoundTripHasEveryCheck) {
  const auto dir = testing::temp_dir("report");
  SuiteContext ctx;
  ctx.out_dir = dir.string();
  ctx.seed = 99;
  std::vector<SuiteResult> results(2);
  results[0].name = "alpha";
  results[0].checks = {make_check("alpha/x", 1.0, 0.0, 2.0), make_check("alpha/y", 5.0, 0.0, 2.0)};
  results[1].name = "beta";
  results[1].checks = {make_check("beta/z", std::nan(""), 0.0, 1.0)};
  EXPECT_EQ(write_report(results, ctx), 2);
  const auto j = nlohmann::json::parse(testing::slurp(dir / "report.json"));
  EXPECT_EQ(j["seed"], 99);
  ASSERT_EQ(j["suites"].size(), 2u);
  EXPECT_EQ(j["suites"][0]["checks"].size(), 2u);
  EXPECT_EQ(j["suites"][0]["checks"][1]["name"], "alpha/y");
  EXPECT_EQ(j["suites"][0]["checks"][1]["pass"], false);
  EXPECT_EQ(j["suites"][0]["checks"][1]["expected"], nlohmann::json({0.0, 2.0}));
  EXPECT_TRUE(j["suites"][1]["checks"][0]["value"].is_null());
  const std::string md = testing::slurp(dir / "report.md");
  EXPECT_NE(md.find("**FAIL** — 1 checks passed, 2 failed"), std::string::npos) << md;
  EXPECT_NE(md.find("`alpha/y`"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(SuiteCli, OrderSuitePassesAndWritesTheReport) {
  const auto dir = testing::temp_dir("suite-order");
  const auto r = testing::run_cli("suite order --quick --out '" + dir.string() + "'");
  EXPECT_EQ(r.code, 0) << r.err << r.out;
  const auto j = nlohmann::json::parse(testing::slurp(dir / "report.json"));
  ASSERT_EQ(j["suites"].size(), 1u);
  EXPECT_EQ(j["suites"][0]["checks"].size(), 16u);  // 4 problems x 4 integrators
  for (const auto& c : j["suites"][0]["checks"]) EXPECT_TRUE(c["pass"].get<bool>()) << c.dump();
  const auto bad = testing::run_cli("suite nosuch --out '" + dir.string() + "'");
  EXPECT_EQ(bad.code, 2);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido::suites
