// `tecido experiment self-contact`: the output contract (72 cells, the claims with their rules),
// bit-identical output at 1 and 2 threads, --calibrate's record, the committed calibration the
// scene file states, and bad usage (exit 2, nothing written). Quick runs of a few cells only.
#include "comparisons/io/source_dir.h"
#include "tests/support/cli_runner.h"
#include "tests/support/command_line_mask.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <set>

namespace tecido {
namespace {

using nlohmann::json;
using testing::run_cli;

std::string q(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

TEST(ExperimentSelfContact, OutputContractAndThreadIndependence) {
  const auto dir = testing::temp_dir("experiment");
  const std::string args = "experiment self-contact --quick --seeds 3 --detector core-mt,core --runs 0-3,13,26,47,70";
  const auto a = run_cli(args + " --threads 1 --out " + q(dir / "t1"));
  const auto b = run_cli(args + " --threads 2 --out " + q(dir / "t2"));
  ASSERT_EQ(a.code, 0) << a.err;
  ASSERT_EQ(b.code, 0) << b.err;
  const std::string j1 = testing::slurp(dir / "t1" / "experiment.json");
  // Identical but for the command line each records (its own --threads and --out).
  EXPECT_EQ(testing::mask_command_line(j1), testing::mask_command_line(testing::slurp(dir / "t2" / "experiment.json")));
  EXPECT_EQ(testing::slurp(dir / "t1" / "experiment.md"), testing::slurp(dir / "t2" / "experiment.md"));
  const json j = json::parse(j1);
  EXPECT_EQ(j["seeds"], 3);
  EXPECT_EQ(j["detectors"], json::array({"core-mt", "core"}));
  ASSERT_EQ(j["cells"].size(), 72u);
  for (const auto& c : j["cells"]) {
    for (const char* key : {"index", "mean", "sd", "ci95", "n", "seed_value", "role", "by_detector"}) EXPECT_TRUE(c.contains(key)) << key;
    const bool ran = std::set<int>{0, 1, 2, 3, 13, 26, 47, 70}.count(c["index"].get<int>()) > 0;
    EXPECT_EQ(c["n"].get<int>(), ran ? 3 : 0) << c["index"];
    EXPECT_TRUE(c["seed_value"].is_number());
  }
  ASSERT_EQ(j["runs"].size(), 8u * 3u);
  for (const auto& r : j["runs"]) {
    EXPECT_EQ(r["frames"].get<long long>(), std::llround(2.0 / r["dt"].get<double>()));
    EXPECT_LE(r["by_detector"]["core-mt"]["contact_frames"].get<long long>(), r["frames"].get<long long>());
    EXPECT_EQ(r["share"], r["by_detector"]["core-mt"]["share"]);
  }
  std::set<std::string> ids;
  for (const auto& c : j["claims"]) {
    for (const char* key : {"id", "statement", "seed", "observed", "ci95", "verdict", "rule"}) EXPECT_TRUE(c.contains(key)) << key;
    EXPECT_TRUE(c["verdict"] == "reproduced" || c["verdict"] == "not reproduced" || c["verdict"] == "inconclusive");
    EXPECT_FALSE(c["rule"].get<std::string>().empty());
    ids.insert(c["id"].get<std::string>());
    if (c["wall_clock"] == true) {
      EXPECT_NE(c["reason"].get<std::string>().find("--runs"), std::string::npos);
    }
  }
  for (const char* id : {"mode3-better", "mode2-worse", "mode1-marginal", "rotation-slower-than-mt", "detection-dominates-step",
                         "premise-gia-fails", "elasticity-level", "step-level"})
    EXPECT_TRUE(ids.count(id)) << id;
  std::filesystem::remove_all(dir);
}

TEST(ExperimentSelfContact, CalibrateWritesARecordWhoseFitIsItsTablesMinimum) {
  const auto dir = testing::temp_dir("calibrate");
  const auto r = run_cli("experiment self-contact --calibrate --quick --seeds 1 --threads 2 --out " + q(dir));
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(testing::slurp(dir / "calibration.json"));
  EXPECT_EQ(j["fit_cells"], json::array({8, 12, 32, 36, 56, 60}));  // no response at 100 steps per second
  double best = 1e300;
  json arg;
  for (const auto& p : j["table"])
    if (p["sse"].is_number() && p["sse"].get<double>() < best) best = p["sse"].get<double>(), arg = p;
  ASSERT_TRUE(arg.is_object());
  EXPECT_EQ(j["fitted"]["air_drag"], arg["air_drag"]);
  EXPECT_EQ(j["fitted"]["swirl_rate"], arg["swirl_rate"]);
  EXPECT_TRUE(std::filesystem::exists(dir / "calibration.md"));
  std::filesystem::remove_all(dir);
}

TEST(ExperimentSelfContact, TheScenesDragAndSwirlAreTheCommittedFit) {
  const std::string data = std::string(TECIDO_SOURCE_DIR) + "/data/";
  const json scene = json::parse(testing::slurp(data + "scenes/seed_fig21_self_contact.json"));
  const json cal = json::parse(testing::slurp(data + "seed_tables/self_contact_calibration.json"));
  EXPECT_EQ(scene["air_drag"], cal["fitted"]["air_drag"]);
  EXPECT_EQ(scene["wind"]["swirl"]["rate"], cal["fitted"]["swirl_rate"]);
  EXPECT_EQ(cal["quick"], false);
}

TEST(ExperimentSelfContact, BadUsageExitsTwoAndWritesNothing) {
  for (const char* args : {"experiment nope", "experiment self-contact --runs 72 --quick", "experiment self-contact --runs x-3",
                           "experiment self-contact --runs 1,1 --quick", "experiment self-contact --seeds 0 --quick",
                           "experiment self-contact --seeds -2 --quick", "experiment self-contact --detector fcl --quick",
                           "experiment self-contact --detector core,core --quick",
                           "experiment self-contact --elasticity-as nothing --quick",
                           "experiment self-contact --strength -1 --quick", "experiment self-contact --scene /nonexistent.json --quick",
                           "experiment self-contact --calibration /nonexistent.json --quick"}) {
    const auto r = run_cli(std::string(args) + " --out /tmp/tecido-never-written");
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists("/tmp/tecido-never-written"));
}

}  // namespace
}  // namespace tecido
