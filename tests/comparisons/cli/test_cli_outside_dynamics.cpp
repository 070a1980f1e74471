// Outside dynamics engines through `tecido suite stability | drift | tradeoff`, as a user runs
// them: the example plug-in's explicit Euler and the Python midpoint find the stable step their
// growth allows on every cell; the plug-in drifts as core's explicit Euler on the same scenes and
// stands on the tradeoff plane where core's explicit Euler stands, its door named; an engine that
// refuses every scene with springs fails each suite's checks for it with "not modelled by NAME",
// never silently.
#include "tests/support/cli_runner.h"
#include "tests/support/outside_fixtures.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>

namespace tecido {
namespace {

using nlohmann::json;
using testing::quoted;
using testing::run_cli;

struct SuiteRun {
  int code;
  std::string err;
  json suite;  ///< the one suite's entry of report.json
  std::string md;
};

SuiteRun suite(const std::string& name, const std::string& args) {
  const auto dir = testing::temp_dir("outside-" + name);
  const auto r = run_cli("suite " + name + " --quick --threads 2 " + args + " --out " + quoted(dir.string()));
  SuiteRun out{r.code, r.err, json(), ""};
  if (std::filesystem::exists(dir / "report.json")) {
    out.suite = json::parse(testing::slurp(dir / "report.json"))["suites"][0];
    out.md = testing::slurp(dir / "report.md");
  }
  std::filesystem::remove_all(dir);
  return out;
}

const json* check(const SuiteRun& r, const std::string& name) {
  for (const auto& c : r.suite["checks"])
    if (c["name"] == name) return &c;
  return nullptr;
}

const std::string kPlugin = "--plugin " + quoted(testing::kExamplePlugin) + " --engines euler-plugin";
const std::string kDoor = "euler-plugin: plug-in " + testing::kExamplePlugin + " (ABI 1)";

std::string refuser() {
  return "--engine-cmd " + quoted("nospring=" + testing::misbehaving_engine("refuse-springs")) + " --engines nospring";
}

TEST(CliOutsideDynamics, StabilityFindsThePluginsEulerAndThePythonMidpointLimitsOnEveryCell) {
  const SuiteRun r = suite("stability", "--plugin " + quoted(testing::kExamplePlugin) + " --engine-cmd " +
                                            quoted("py=" + testing::kPythonEngine) + " --engines euler-plugin,py");
  ASSERT_EQ(r.code, 0) << r.err;
  const json* c = check(r, "stability/euler-plugin/grid_spread");
  ASSERT_TRUE(c);
  EXPECT_TRUE((*c)["pass"].get<bool>()) << c->dump();
  const json& cells = r.suite["data"]["outside"]["euler-plugin"];
  ASSERT_EQ(cells.size(), 9u);
  // Explicit Euler grows by sqrt(1 + (h omega)^2) per step: over 100 periods the amplitude reaches
  // 1000 x near h omega = 0.022 (100 pi z ~ ln 1000; tests/.../test_outside_stability.cpp solves it).
  for (const auto& cell : cells) EXPECT_NEAR(cell["h_omega"].get<double>(), 0.022, 5e-4) << cell.dump();
  // The explicit midpoint grows by sqrt(1 + z^4 / 4) per step: 1000 x at a period's end near z = 0.45202
  // (the closed form, solved in test_outside_stability.cpp).
  const json* py = check(r, "stability/py/grid_spread");
  ASSERT_TRUE(py);
  EXPECT_TRUE((*py)["pass"].get<bool>()) << py->dump();
  ASSERT_EQ(r.suite["data"]["outside"]["py"].size(), 9u);
  for (const auto& cell : r.suite["data"]["outside"]["py"]) EXPECT_NEAR(cell["h_omega"].get<double>(), 0.45202, 1e-4);
  EXPECT_NE(r.md.find("- " + kDoor), std::string::npos);
  EXPECT_NE(r.md.find("- py: process `" + testing::kPythonEngine + "`"), std::string::npos);
}

TEST(CliOutsideDynamics, DriftOfThePluginIsCoresExplicitEuler) {
  const SuiteRun r = suite("drift", kPlugin);
  ASSERT_EQ(r.code, 0) << r.err;
  int scenes = 0;
  for (const auto& [scene, engines] : r.suite["data"].items()) {
    if (!engines.contains("euler-plugin")) continue;
    ++scenes;
    const json &o = engines["euler-plugin"], &core = engines["euler"];
    for (const char* f : {"max_rel_energy", "final_rel_energy", "growth_rate", "angular_momentum_error"})
      EXPECT_NEAR(o[f].get<double>(), core[f].get<double>(), 1e-6 * std::abs(core[f].get<double>())) << scene << " " << f;
    const json* c = check(r, "drift/" + scene + "/euler-plugin/momentum");
    ASSERT_TRUE(c) << scene;
    EXPECT_TRUE((*c)["pass"].get<bool>()) << c->dump();
  }
  EXPECT_EQ(scenes, 2);  // two-body-3d, free-cloth
  EXPECT_NE(r.md.find("- " + kDoor), std::string::npos);
}

TEST(CliOutsideDynamics, TradeoffPutsThePluginOnThePlaneWithItsDoor) {
  const SuiteRun r = suite("tradeoff", kPlugin);
  ASSERT_EQ(r.code, 0) << r.err;
  const json* c = check(r, "tradeoff/16/euler-plugin/reproducible");
  ASSERT_TRUE(c);
  EXPECT_TRUE((*c)["pass"].get<bool>()) << c->dump();
  EXPECT_FALSE(check(r, "tradeoff/32/euler-plugin/reproducible"));  // beyond its range
  EXPECT_NE(r.md.find(kDoor), std::string::npos);
  EXPECT_NE(r.md.find("door included"), std::string::npos);
  // Explicit Euler through the door: each point as core's explicit Euler at the same step (diverged
  // where it diverged, the same error where it ran); its cost is its own timing, not compared.
  std::map<double, json> core;
  for (const auto& run : r.suite["data"]["cloth16"]["runs"])
    if (run["engine"] == "core-euler") core[run["h"].get<double>()] = run;
  int points = 0, counted = 0;
  for (const auto& run : r.suite["data"]["cloth16"]["runs"]) {
    if (run["engine"] != "euler-plugin") continue;
    ++points;
    const json& c = core.at(run["h"].get<double>());
    EXPECT_EQ(run["counted"], c["counted"]) << run.dump();
    counted += run["counted"].get<bool>();
    if (c["error"].is_number())
      EXPECT_NEAR(run["error"].get<double>(), c["error"].get<double>(), 1e-9 * c["error"].get<double>()) << run.dump();
    else
      EXPECT_TRUE(run["error"].is_null()) << run.dump();
  }
  EXPECT_EQ(points, 5);  // every swept step of the quick 16 x 16 cloth
  EXPECT_GE(counted, 1);
}

// Each suite's checks for an engine that refuses every scene with springs: failed, each naming the
// engine and what it does not model (`refused`: how many checks of the suite concern such scenes).
void expect_refused_scenes_fail(const std::string& name, int refused_checks) {
  const SuiteRun r = suite(name, refuser());
  EXPECT_EQ(r.code, 1) << name << r.err;
  int refused = 0;
  for (const auto& c : r.suite["checks"]) {
    if (c["name"].get<std::string>().find("/nospring/") == std::string::npos) continue;
    EXPECT_FALSE(c["pass"].get<bool>()) << c.dump();
    refused += c["reason"].get<std::string>().find("not modelled by nospring: springs: not modelled") != std::string::npos;
  }
  EXPECT_EQ(refused, refused_checks) << name;
  EXPECT_NE(r.md.find("not modelled by nospring"), std::string::npos) << name;
}

TEST(CliOutsideDynamics, RefusedScenesFailTheStabilityChecksNamingTheEngine) { expect_refused_scenes_fail("stability", 1); }
TEST(CliOutsideDynamics, RefusedScenesFailTheDriftChecksNamingTheEngine) { expect_refused_scenes_fail("drift", 2); }
TEST(CliOutsideDynamics, RefusedScenesFailTheTradeoffChecksNamingTheEngine) { expect_refused_scenes_fail("tradeoff", 1); }

}  // namespace
}  // namespace tecido
