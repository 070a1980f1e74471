// Outside engines in the stability suite: the example plug-in's explicit Euler has no stable step,
// so its "largest stable step" over 100 periods is where its growth per step sqrt(1 + (h omega)^2)
// reaches the amplitude bound; the bisection must find that h omega on every cell. Planted results:
// a failed or empty cell fails the spread check with a reason naming the cell.
#include "comparisons/engines/outside/plugin_engine.h"
#include "comparisons/engines/outside/plugin_library.h"
#include "comparisons/engines/outside/process_engine.h"
#include "comparisons/suites/stability/cases.h"
#include "comparisons/suites/stability/outside_stability.h"
#include "comparisons/suites/stability/theory.h"
#include "tests/support/outside_fixtures.h"
#include "tests/support/refusing_engine.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace tecido::suites::stability {
namespace {

outside::OutsideEnginePtr euler_plugin() {
  for (auto& e : outside::plugin_engines(outside::PluginLibrary::load(testing::kExamplePlugin)))
    if (e->name() == "euler-plugin") return e;
  return nullptr;
}

/// Explicit Euler on x'' = -omega^2 x multiplies r = |(x, v / omega)| by sqrt(1 + z^2) per step, z = h omega,
/// and turns it by atan z. After N = ceil(P 2 pi / z) steps its x is r_N cos(N atan z - 2 pi P).
double euler_x_after(double z, double periods) {
  const double n = std::ceil(periods * 2.0 * kPi / z);
  return std::pow(1.0 + z * z, n / 2.0) * std::cos(n * std::atan(z) - 2.0 * kPi * periods);
}

TEST(OutsideStability, EulerPluginAgainstItsGrowth) {
  const auto e = euler_plugin();
  const double bound = 1000.0, periods = 100.0;
  // The z where x after 100 periods reaches the bound, by bisection on the closed form.
  double lo = 0.01, hi = 0.05;
  for (int i = 0; i < 60; ++i) (euler_x_after(0.5 * (lo + hi), periods) <= bound ? lo : hi) = 0.5 * (lo + hi);
  const double z = lo;
  EXPECT_NEAR(z, 0.022, 5e-4);  // 100 pi z ~ ln 1000
  // ks = 4, m = 1: omega = 2. Well below and above the limit (the period-end checks see the growth).
  EXPECT_TRUE(outside_stable(*e, 4.0, 1.0, 0.98 * z / 2.0, periods, bound));
  EXPECT_FALSE(outside_stable(*e, 4.0, 1.0, 1.02 * z / 2.0, periods, bound));

  Settings s = settings(true);
  OutsidePlan plan = outside_plan(s, {e});
  ASSERT_EQ(plan.cases(), 9u);
  for (std::size_t i : {0u, 4u, 8u}) {  // the grid's diagonal: omega from sqrt(10) to sqrt(10)
    const StableStep st = step_from_json(run_outside_case(plan, i));
    ASSERT_TRUE(st.found);
    const double ks = s.outside.stiffnesses[i / 3], m = s.outside.masses[i % 3];
    EXPECT_NEAR(st.h * std::sqrt(ks / m), z, 2e-3 * z) << "cell " << i;
  }
}

/// The explicit midpoint method on x'' = -omega^2 x maps (x, v / omega) by r R(theta) per step,
/// r = sqrt(1 + z^4 / 4), theta = atan2(z, 1 - z^2 / 2), z = h omega: from rest at x = 1 its x after
/// k steps is r^k cos(k theta). Whether it stays within `bound` at the end of every period, as
/// outside_stable checks it (a period is ceil(2 pi / z) steps, the run ceil(P 2 pi / z)).
bool midpoint_within(double z, double periods, double bound) {
  const long long n = static_cast<long long>(std::ceil(periods * 2.0 * kPi / z));
  const long long per = static_cast<long long>(std::ceil(2.0 * kPi / z));
  const double r = std::sqrt(1.0 + z * z * z * z / 4.0), theta = std::atan2(z, 1.0 - z * z / 2.0);
  for (long long k = std::min(per, n);; k = std::min(k + per, n)) {
    if (!(std::abs(std::pow(r, static_cast<double>(k)) * std::cos(k * theta)) <= bound)) return false;
    if (k == n) return true;
  }
}

TEST(OutsideStability, PythonMidpointAgainstItsGrowth) {
  using namespace std::chrono_literals;
  const auto py = outside::ProcessEngine::start("py", testing::kPythonEngine, 30s);
  const double bound = 1000.0, periods = 100.0;
  double lo = 0.3, hi = 0.6;
  ASSERT_TRUE(midpoint_within(lo, periods, bound));
  ASSERT_FALSE(midpoint_within(hi, periods, bound));
  for (int i = 0; i < 60; ++i) (midpoint_within(0.5 * (lo + hi), periods, bound) ? lo : hi) = 0.5 * (lo + hi);
  const double z = lo;  // about (4 ln 1000 / (100 pi))^(1/3) = 0.44
  EXPECT_NEAR(z, 0.452, 1e-3);
  // ks = 9, m = 1: omega = 3.
  EXPECT_TRUE(outside_stable(*py, 9.0, 1.0, 0.97 * z / 3.0, periods, bound));
  EXPECT_FALSE(outside_stable(*py, 9.0, 1.0, 1.03 * z / 3.0, periods, bound));
  const long long before = py->round_trips();
  const double h = 0.97 * z / 3.0;
  outside_stable(*py, 9.0, 1.0, h, periods, bound);
  const long long n = steps_for(periods, 3.0, h), per = steps_for(1.0, 3.0, h);
  EXPECT_EQ(py->round_trips() - before, 1 + (n + per - 1) / per);  // create, then one step request per period
}

using Refuser = testing::RefusingEngine;

TEST(OutsideStability, RefusalThrowsNotModelled) {
  Refuser r;
  try {
    outside_stable(r, 1.0, 1.0, 0.1, 1.0, 1000.0);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "not modelled by refuser: springs: not modelled");
  }
}

TEST(OutsideStability, PlantedResultsFeedTheSpreadCheck) {
  Settings s = settings(true);
  auto engine = std::make_shared<Refuser>();
  OutsidePlan plan = outside_plan(s, {engine});
  const Tolerances tol(io::Json::parse(R"({"stability":{"grid_spread":1e-5}})"), "planted");
  auto run = [&](std::vector<io::Json> results) {
    CheckList checks;
    declare_outside_checks(checks, plan, tol);
    io::Json data;
    const std::string md = outside_tables(plan, results, checks, data);
    return std::make_pair(checks.finish().at(0), md);
  };
  std::vector<io::Json> results;
  for (std::size_t i = 0; i < 9; ++i) {
    const double omega = std::sqrt(s.outside.stiffnesses[i / 3] / s.outside.masses[i % 3]);
    results.push_back(step_json({true, 0.5 / omega, 0.6 / omega, 10}));
  }
  auto [ok, md] = run(results);
  EXPECT_EQ(ok.name, "stability/refuser/grid_spread");
  EXPECT_TRUE(ok.pass);
  EXPECT_NEAR(ok.value, 0.0, 1e-15);
  EXPECT_NE(md.find("| refuser | 0.5 |"), std::string::npos) << md;

  results[4] = io::Json{{"error", "case 4 threw: not modelled by refuser: springs: not modelled"}};
  auto [failed, md2] = run(results);
  EXPECT_FALSE(failed.pass);
  EXPECT_NE(failed.reason.find("ks = 10 N/m, m = 1 kg: case 4 threw: not modelled by refuser"), std::string::npos)
      << failed.reason;

  results[4] = step_json({false, 0.0, 0.01, 20});
  auto [none, md3] = run(results);
  EXPECT_FALSE(none.pass);
  EXPECT_NE(none.reason.find("no stable step at ks = 10 N/m, m = 1 kg"), std::string::npos) << none.reason;
}

}  // namespace
}  // namespace tecido::suites::stability
