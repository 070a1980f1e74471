// Outside engines from the command line, as a user runs them: the example C plug-in and the
// Python example through `tecido tritri` and `tecido suite order`; a lying plug-in (explicit Euler
// claiming order 2) caught by a failing check; every broken door one line on stderr, exit 2, no
// report; a refused scene reported as "not modelled by NAME".
#include "comparisons/io/tri_pairs.h"
#include "tests/support/cli_runner.h"
#include "tests/support/outside_fixtures.h"
#include "tests/support/rejection.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace tecido {
namespace {

using nlohmann::json;
using testing::quoted;
using testing::run_cli;

std::string hand_pairs_file(const std::filesystem::path& dir) {
  std::vector<io::TriPair> pairs;
  for (const auto& p : testing::hand_pairs()) pairs.push_back({p.id, p.a, p.b, {}});
  const std::string path = (dir / "pairs.json").string();
  testing::write_text(path, io::tri_pairs_to_json(pairs).dump());
  return path;
}

/// The fitted orders of `engine` in report.json's order data, per problem.
std::vector<double> fitted_orders(const json& report, const std::string& engine) {
  std::vector<double> out;
  for (const auto& s : report["suites"])
    if (s["name"] == "order")
      for (const auto& [problem, engines] : s["data"].items())
        if (engines.contains(engine) && engines[engine]["fitted_order"].is_number())
          out.push_back(engines[engine]["fitted_order"].get<double>());
  return out;
}

std::vector<json> checks_of(const json& report, const std::string& engine) {
  std::vector<json> out;
  for (const auto& s : report["suites"])
    for (const auto& c : s["checks"])
      if (c["name"].get<std::string>().size() > engine.size() &&
          c["name"].get<std::string>().compare(c["name"].get<std::string>().size() - engine.size(), engine.size(), engine) == 0)
        out.push_back(c);
  return out;
}

TEST(CliOutside, TritriPluginMissesCountedAgainstExact) {
  const auto dir = testing::temp_dir("outside-tritri");
  const auto r = run_cli("tritri --pairs " + quoted(hand_pairs_file(dir)) + " --plugin " + quoted(testing::kExamplePlugin) +
                         " --engines mt-plugin,core-mt,exact --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json out = json::parse(r.out);
  int misses = 0;
  const auto hand = testing::hand_pairs();
  for (std::size_t k = 0; k < hand.size(); ++k) {
    const json& row = out["results"][k];
    EXPECT_EQ(row["id"], hand[k].id);
    EXPECT_EQ(row["exact"], hand[k].truth) << hand[k].id;
    EXPECT_EQ(row["mt-plugin"], hand[k].mt) << hand[k].id;
    EXPECT_EQ(row["mt-plugin"], row["core-mt"]) << hand[k].id;  // the plug-in is the seed's MT, as core-mt
    misses += row["exact"].get<bool>() && !row["mt-plugin"].get<bool>();
  }
  EXPECT_EQ(misses, 3);  // stab, coplanar, touching
  std::filesystem::remove_all(dir);
}

TEST(CliOutside, TritriPythonEngineAgainstExact) {
  const auto dir = testing::temp_dir("outside-tritri-py");
  const auto r = run_cli("tritri --pairs " + quoted(hand_pairs_file(dir)) + " --engine-cmd " +
                         quoted("py=" + testing::kPythonEngine) + " --engines py,exact --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json out = json::parse(r.out);
  const auto hand = testing::hand_pairs();
  int misses = 0;
  for (std::size_t k = 0; k < hand.size(); ++k) {
    EXPECT_EQ(out["results"][k]["py"], hand[k].edges) << hand[k].id;
    misses += hand[k].truth && !out["results"][k]["py"].get<bool>();
  }
  EXPECT_EQ(misses, 1);  // the coplanar pair
  std::filesystem::remove_all(dir);
}

TEST(CliOutside, TritriSuiteCatchesThePluginsMisses) {
  const auto dir = testing::temp_dir("outside-tritri-suite");
  const auto r = run_cli("suite tritri --quick --threads 2 --plugin " + quoted(testing::kExamplePlugin) +
                         " --engines mt-plugin,core-mt --out " + quoted(dir.string()));
  EXPECT_EQ(r.code, 1) << r.err;  // the seed's MT misses touching and coplanar pairs: its checks fail
  const json report = json::parse(testing::slurp(dir / "report.json"));
  const json& data = report["suites"][0]["data"];
  ASSERT_TRUE(data.contains("mt-plugin"));
  for (const auto& [family, cell] : data["core-mt"].items()) {
    if (!cell.is_object()) continue;
    EXPECT_EQ(data["mt-plugin"][family], cell) << family;  // the same test through the door: the same answers
  }
  // Coplanar pairs: every det is 0, so MT answers false; it agrees exactly on the non-intersecting ones.
  EXPECT_LT(data["mt-plugin"]["coplanar"]["agree"].get<long>(), data["mt-plugin"]["coplanar"]["pairs"].get<long>());
  const auto checks = checks_of(report, "/agreement/coplanar");
  bool plugin_checked = false;
  for (const auto& c : checks)
    if (c["name"] == "tritri/mt-plugin/agreement/coplanar") {
      plugin_checked = true;
      EXPECT_FALSE(c["pass"].get<bool>());
      EXPECT_EQ(c["tolerance"], "/tritri/outside_min_agreement");
    }
  EXPECT_TRUE(plugin_checked);
  for (const auto& c : report["suites"][0]["checks"])
    EXPECT_EQ(c["name"].get<std::string>().find("core-mt"), std::string::npos);  // core-mt: reported, not checked
  std::filesystem::remove_all(dir);
}

// The plug-in is given by a path relative to the working directory; the report names its
// absolute path (so that the report can be read from anywhere).
TEST(CliOutside, OrderSuiteFitsThePluginsEulerAtOne) {
  const auto dir = testing::temp_dir("outside-order");
  const std::filesystem::path plugin(testing::kExamplePlugin);
  const auto r = testing::run_cli_with("cd " + quoted(plugin.parent_path().string()),
                                       "suite order --quick --threads 2 --plugin " + quoted("./" + plugin.filename().string()) +
                                           " --engines euler-plugin --out " + quoted(dir.string()));
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  const json report = json::parse(testing::slurp(dir / "report.json"));
  const auto orders = fitted_orders(report, "euler-plugin");
  ASSERT_EQ(orders.size(), 4u);
  for (double p : orders) EXPECT_NEAR(p, 1.0, 0.15);
  const auto checks = checks_of(report, "/euler-plugin");
  ASSERT_EQ(checks.size(), 4u);
  for (const auto& c : checks) EXPECT_TRUE(c["pass"].get<bool>()) << c.dump();
  ASSERT_EQ(report["outside_engines"].size(), 3u);  // mt-plugin, euler-plugin, sampled-ccd
  EXPECT_EQ(report["outside_engines"][1]["door"], "plug-in " + testing::kExamplePlugin + " (ABI 1)");
  const std::string md = testing::slurp(dir / "report.md");
  EXPECT_NE(md.find("| euler-plugin | plug-in " + testing::kExamplePlugin + " (ABI 1) | dynamics | 1 |"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(CliOutside, LyingPluginFailsItsClaim) {
  const auto dir = testing::temp_dir("outside-liar");
  const auto r = run_cli("suite order --quick --threads 2 --plugin " + quoted(testing::kLiarPlugin) +
                         " --engines euler-liar --out " + quoted(dir.string()));
  EXPECT_EQ(r.code, 1) << r.err << r.out;
  const json report = json::parse(testing::slurp(dir / "report.json"));
  const auto checks = checks_of(report, "/euler-liar");
  ASSERT_EQ(checks.size(), 4u);
  for (const auto& c : checks) {
    EXPECT_FALSE(c["pass"].get<bool>()) << c.dump();
    EXPECT_NEAR(c["value"].get<double>(), 1.0, 0.15);  // what it delivers
    EXPECT_NEAR(c["expected"][0].get<double>() + c["expected"][1].get<double>(), 4.0, 1e-12);  // the band around 2
  }
  std::filesystem::remove_all(dir);
}

TEST(CliOutside, LyingProcessFailsItsClaim) {
  const auto dir = testing::temp_dir("outside-liar-py");
  const auto r = run_cli("suite order --quick --threads 2 --engine-cmd " +
                         quoted("pyliar=" + testing::misbehaving_engine("claim-2")) + " --engines pyliar --out " +
                         quoted(dir.string()));
  EXPECT_EQ(r.code, 1) << r.err << r.out;
  const json report = json::parse(testing::slurp(dir / "report.json"));
  const auto orders = fitted_orders(report, "pyliar");
  ASSERT_EQ(orders.size(), 4u);
  for (double p : orders) EXPECT_NEAR(p, 1.0, 0.15);  // explicit Euler, whatever hello says
  const auto checks = checks_of(report, "/pyliar");
  ASSERT_EQ(checks.size(), 4u);
  for (const auto& c : checks) EXPECT_FALSE(c["pass"].get<bool>()) << c.dump();
  EXPECT_EQ(report["outside_engines"][0]["claimed_order"], 2.0);
  std::filesystem::remove_all(dir);
}

TEST(CliOutside, OrderSuiteFitsThePythonMidpointAtTwo) {
  const auto dir = testing::temp_dir("outside-order-py");
  const auto r = run_cli("suite order --quick --threads 2 --engine-cmd " + quoted("py=" + testing::kPythonEngine) +
                         " --engines py --out " + quoted(dir.string()));
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  const json report = json::parse(testing::slurp(dir / "report.json"));
  const auto orders = fitted_orders(report, "py");
  ASSERT_EQ(orders.size(), 4u);
  for (double p : orders) EXPECT_NEAR(p, 2.0, 0.15);
  EXPECT_EQ(report["outside_engines"][0]["door"], "process `" + testing::kPythonEngine + "`");
  EXPECT_EQ(report["outside_engines"][0]["claimed_order"], 2.0);
  std::filesystem::remove_all(dir);
}

TEST(CliOutside, RefusedSceneIsReportedNotModelled) {
  const auto dir = testing::temp_dir("outside-refuse");
  const auto r = run_cli("suite order --quick --threads 2 --engine-cmd " +
                         quoted("nodrag=" + testing::misbehaving_engine("refuse-drag")) + " --engines nodrag --out " +
                         quoted(dir.string()));
  EXPECT_EQ(r.code, 1) << r.err;  // the drag problems cannot confirm its claim
  const json report = json::parse(testing::slurp(dir / "report.json"));
  int refused = 0, passed = 0;
  for (const auto& c : checks_of(report, "/nodrag")) {
    if (c.contains("reason") && c["reason"].get<std::string>().find("not modelled by nodrag: linear drag: not modelled") !=
                                    std::string::npos)
      ++refused;
    passed += c["pass"].get<bool>();
  }
  EXPECT_EQ(refused, 2);  // damped, projectile-drag
  EXPECT_EQ(passed, 2);   // harmonic, two-body-spring: explicit Euler, order 1 as claimed
  EXPECT_NE(testing::slurp(dir / "report.md").find("not modelled by nodrag"), std::string::npos);
  std::filesystem::remove_all(dir);
}

/// The last line of `err` (a suite's progress line may precede the error line).
std::string last_line(const std::string& err) {
  std::string e = err;
  if (!e.empty() && e.back() == '\n') e.pop_back();
  const std::size_t nl = e.rfind('\n');
  return nl == std::string::npos ? e : e.substr(nl + 1);
}

/// Runs `args` expecting exit 2, one error line on stderr ("tecido: ...") containing `expect`, and
/// nothing written: no report in the out dir (when `out`), nothing on stdout.
void expect_door_error(const std::string& args, const std::string& expect, bool out = true) {
  const auto dir = testing::temp_dir("outside-error");
  const auto r = run_cli(args + (out ? " --out " + quoted((dir / "out").string()) : std::string()));
  EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
  const std::string line = last_line(r.err);
  EXPECT_EQ(line.rfind("tecido: ", 0), 0u) << r.err;
  EXPECT_EQ(r.err.find("tecido: "), r.err.rfind("tecido: ")) << r.err;  // one error line
  EXPECT_NE(line.find(expect), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "report.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "report.md"));
  std::filesystem::remove_all(dir);
}

TEST(CliOutside, BrokenPluginsAreOneLineExitTwo) {
  expect_door_error("suite order --plugin /nonexistent/libengine.so", "plug-in /nonexistent/libengine.so: dlopen:");
  expect_door_error("suite order --plugin " + quoted(testing::kNoEntryPlugin),
                    "tecido_plugin_entry: symbol not found");
  expect_door_error("suite order --plugin " + quoted(testing::kFutureAbiPlugin),
                    "ABI version mismatch: the plug-in was built for ABI 99, this tecido speaks ABI 1");
}

TEST(CliOutside, MisbehavingProcessesAreOneLineExitTwo) {
  const auto cmd = [](const std::string& mode) {
    return "suite order --quick --threads 2 --engines bad --engine-timeout 0.5 --engine-cmd " +
           quoted("bad=" + testing::misbehaving_engine(mode));
  };
  expect_door_error(cmd("die-at-step"), "op step: closed its output without a reply: exited with status 3; its stderr "
                                        "ends: boom: integrator diverged");
  expect_door_error(cmd("hang-at-step"), "op step: no reply within 0.5 s");
  expect_door_error(cmd("garbage-at-step"), "op step: malformed JSON reply: \"this is not json\"");
}

TEST(CliOutside, TritriProcessDyingMidRunPrintsNoResults) {
  const auto dir = testing::temp_dir("outside-tritri-die");
  expect_door_error("tritri --json --pairs " + quoted(hand_pairs_file(dir)) + " --engines exact,bad --engine-cmd " +
                        quoted("bad=" + testing::misbehaving_engine("die-at-tri")),
                    "engine bad (`" + testing::misbehaving_engine("die-at-tri") + "`): op tri_tri:", /*out=*/false);
  std::filesystem::remove_all(dir);
}

TEST(CliOutside, NameClashesAndBadSpecsAreUsageErrors) {
  expect_door_error("suite order --engine-cmd " + quoted("core=" + testing::kPythonEngine), "name is taken");
  expect_door_error("suite order --engine-cmd " + quoted("nameonly"), "--engine-cmd: expected NAME=COMMAND");
  expect_door_error("suite order --engines nosuch", "unknown suite engine \"nosuch\"");
}

}  // namespace
}  // namespace tecido
