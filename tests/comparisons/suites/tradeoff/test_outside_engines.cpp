// Outside engines in the tradeoff suite (comparisons/suites/tradeoff/outside_engines.h): the
// example plug-in's explicit Euler and the Python example's midpoint, run through their doors in
// chunks, end where core's integrator of the same method ends (the same arithmetic up to the order
// of operations); a process pays one round trip per chunk; a refused cloth is its point's status
// "not modelled by NAME"; the reproducibility check is set from the points or failed with their
// statuses; the report names the door and says the cost includes it.
#include "comparisons/engines/outside/plugin_engine.h"
#include "comparisons/engines/outside/plugin_library.h"
#include "comparisons/engines/outside/process_engine.h"
#include "comparisons/suites/tradeoff/cases.h"
#include "comparisons/suites/tradeoff/curtain.h"
#include "comparisons/suites/tradeoff/distances.h"
#include "comparisons/suites/tradeoff/outside_engines.h"
#include "comparisons/suites/tradeoff/points.h"
#include "tests/support/outside_fixtures.h"
#include "tests/support/refusing_engine.h"

#include <gtest/gtest.h>

#include <chrono>

namespace tecido::suites::tradeoff {
namespace {

using namespace std::chrono_literals;

outside::OutsideEnginePtr euler_plugin() {
  for (auto& e : outside::plugin_engines(outside::PluginLibrary::load(testing::kExamplePlugin)))
    if (e->name() == "euler-plugin") return e;
  return nullptr;
}

// A 4 x 4 hanging cloth for 0.1 s at h = 1/1000 s: 100 steps, one chunk of 64 and one of 36.
constexpr double kH = 1e-3, kSeconds = 0.1;

TEST(TradeoffOutside, EulerPluginEndsWhereCoresEulerEnds) {
  const Scene cloth = hanging_cloth(4);
  const TradeoffEngine e = outside_tradeoff_engine(euler_plugin(), settings(true));
  EXPECT_EQ(e.name, "euler-plugin");
  EXPECT_EQ(e.door, "plug-in " + testing::kExamplePlugin + " (ABI 1)");
  EXPECT_EQ(e.door_chunk, kOutsideChunk);
  EXPECT_EQ(e.max_n, settings(true).outside.max_side);
  const auto x = e.run(cloth, kH, kSeconds);
  const auto core = core_tradeoff_engine(IntegratorKind::Euler).run(cloth, kH, kSeconds);
  ASSERT_TRUE(x && core);
  EXPECT_LT(max_abs_difference(*x, *core), 1e-12);
  EXPECT_GT(max_abs_difference(*x, cloth.particles.x), 1e-3);  // it moved: the comparison is not vacuous
}

TEST(TradeoffOutside, PythonMidpointEndsWhereCoresMidpointEndsInOneRoundTripPerChunk) {
  const Scene cloth = hanging_cloth(4);
  const auto py = outside::ProcessEngine::start("py", testing::kPythonEngine, 30s);
  const TradeoffEngine e = outside_tradeoff_engine(py, settings(true));
  const long long before = py->round_trips();
  const auto x = e.run(cloth, kH, kSeconds);
  EXPECT_EQ(py->round_trips() - before, 1 + 2);  // create, then 64 + 36 steps
  const auto core = core_tradeoff_engine(IntegratorKind::Midpoint).run(cloth, kH, kSeconds);
  ASSERT_TRUE(x && core);
  EXPECT_LT(max_abs_difference(*x, *core), 1e-12);
}

TEST(TradeoffOutside, RefusedClothIsNotModelled) {
  const TradeoffEngine e = outside_tradeoff_engine(std::make_shared<testing::RefusingEngine>(), settings(true));
  const reference::GuardedRun r = e.run_guarded(hanging_cloth(4), kH, kSeconds);
  EXPECT_FALSE(r.x);
  const io::Json result = {{"x", nullptr}, {"reason", r.reason}, {"seconds", 0.0}, {"rerun_diff", 0.0}};
  const CaseLayout layout = case_layout({{4, 1}}, 1);
  std::vector<io::Json> results(layout.cases, io::Json::object());
  results[layout.point_case(0, 0, 0)] = result;
  const auto pts = size_points(layout, 0, {kH}, {e}, results, std::nullopt, settings(true));
  ASSERT_EQ(pts.size(), 1u);
  EXPECT_EQ(pts[0].status, "not modelled by refuser: springs: not modelled");
}

TEST(TradeoffOutside, ReproducibleCheckFromThePoints) {
  Settings s = settings(true);
  s.sizes = {{16, 3}, {32, 3}};
  std::vector<TradeoffEngine> engines = {core_tradeoff_engine(IntegratorKind::Euler),
                                         outside_tradeoff_engine(std::make_shared<testing::RefusingEngine>(), s)};
  const Tolerances tol(io::Json::parse(R"({"tradeoff":{"reproducible_max_abs_diff":0.0}})"), "planted");
  CheckList checks;
  declare_outside_checks(checks, s, engines, tol);
  EXPECT_TRUE(checks.declared("tradeoff/16/refuser/reproducible"));
  EXPECT_FALSE(checks.declared("tradeoff/32/refuser/reproducible"));  // beyond its range: not run
  EXPECT_FALSE(checks.declared("tradeoff/16/core-euler/reproducible"));
  SizeAnalysis a;
  a.n = 16;
  Point ran;
  ran.engine = 1, ran.h = 0.5, ran.x = {Vec3::Zero()}, ran.rerun_diff = 0.0;
  Point refused;
  refused.engine = 1, refused.h = 0.25, refused.status = "not modelled by refuser: springs";
  a.points = {ran, refused};
  CheckList set = checks;
  record_outside_checks(set, a, engines);
  const auto ok = set.finish();
  ASSERT_EQ(ok.size(), 1u);
  EXPECT_TRUE(ok[0].pass);
  a.points = {refused};
  record_outside_checks(checks, a, engines);
  const auto failed = checks.finish();
  EXPECT_FALSE(failed[0].pass);
  EXPECT_EQ(failed[0].reason, "no run returned positions (2^-2: not modelled by refuser: springs)");
  const std::string md = outside_markdown(engines);
  EXPECT_NE(md.find("- refuser: test;"), std::string::npos) << md;
  EXPECT_NE(md.find("round trip"), std::string::npos) << md;
  EXPECT_EQ(outside_markdown({engines[0]}), "");
}

}  // namespace
}  // namespace tecido::suites::tradeoff
