// Determinism (docs/design.md section 4): the same scene, seed and build give bit-identical results,
// whatever the thread count. Checked from outside, through the CLI:
//  - `tecido run SCENE --json` twice per scene of data/scenes/: identical bytes on stdout, and
//    `--out DIR` gives identical result.json bytes;
//  - `tecido suite order|plane --quick` at --threads 1 and 2, twice each: report.json identical
//    once the timings are removed ("seconds" and the ns-per-pair/case entries);
//  - `tecido experiment self-contact --quick` (a subset of its runs) likewise.
// Files name the command line that wrote them (comparisons/io/provenance.h), which differs in
// --out and --threads: it is checked to be that run's, then masked (tests/support/command_line_mask.h).
#include "comparisons/io/source_dir.h"
#include "tests/support/cli_runner.h"
#include "tests/support/command_line_mask.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace tecido {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::run_cli;

/// Wall-clock entries, the only part of a report outside the determinism promise.
bool is_timing_key(const std::string& key) { return key == "seconds" || key.rfind("ns_per", 0) == 0; }

/// Removes timing entries at any depth and returns how many were removed.
int strip_timings(json& j) {
  int removed = 0;
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end();) {
      if (is_timing_key(it.key())) {
        it = j.erase(it);
        ++removed;
      } else {
        removed += strip_timings(*it);
        ++it;
      }
    }
  } else if (j.is_array()) {
    for (auto& e : j) removed += strip_timings(e);
  }
  return removed;
}

/// The file's JSON without timings and with its command line masked, printed the way the CLI
/// prints it (dump(2)): comparing these bytes compares every value exactly (doubles are printed to
/// round-trip). The command line must be the one that wrote the file (`args` in it).
std::string without_timings(const fs::path& file, const std::string& args, int* removed = nullptr) {
  json j = json::parse(testing::slurp(file));
  EXPECT_NE(j["tecido"]["command_line"].get<std::string>().find(args), std::string::npos) << j["tecido"];
  j = testing::mask_command_line_json(j);
  const int n = strip_timings(j);
  if (removed) *removed = n;
  return j.dump(2);
}

std::vector<fs::path> scene_files() {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(fs::path(TECIDO_SOURCE_DIR) / "data" / "scenes"))
    if (e.path().extension() == ".json") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(Determinism, RunJsonIsByteIdenticalAcrossRuns) {
  const auto scenes = scene_files();
  ASSERT_GE(scenes.size(), 5u);
  for (const auto& scene : scenes) {
    const auto a = run_cli("run '" + scene.string() + "' --json");
    const auto b = run_cli("run '" + scene.string() + "' --json");
    ASSERT_EQ(a.code, 0) << scene << "\n" << a.err;
    ASSERT_EQ(b.code, 0) << scene << "\n" << b.err;
    EXPECT_FALSE(a.out.empty()) << scene;
    EXPECT_EQ(a.out, b.out) << scene;
    // And another integrator than the scene's, so that all four are covered across the scenes.
    const auto c = run_cli("run '" + scene.string() + "' --json --integrator midpoint --steps 50");
    const auto d = run_cli("run '" + scene.string() + "' --json --integrator midpoint --steps 50");
    ASSERT_EQ(c.code, 0) << scene << "\n" << c.err;
    EXPECT_EQ(c.out, d.out) << scene;
  }
}

// `tecido run --threads N`: the self-collision detection runs in shares, the result must not
// change. The 128 x 128 falling cloth (bench/scenes/cloth_fold_128.json, about 32k triangles:
// thousands of candidates, so the detectors do cut their work) with discrete detection and
// edge mode 3, and with continuous detection and impulses, 40 steps each. (Within 40 steps the
// cloth has not landed: no contact yet, so this checks the plumbing of --threads; the answers
// in shares with contacts are checked by SameAnswerAtEveryThreadCount in tests/core/cloth/.)
TEST(Determinism, RunIsByteIdenticalAtEveryDetectionThreadCount) {
  const auto dir = testing::temp_dir("det-run-threads");
  // The fold benchmark's cloth at 40 x 40 under 400 m/s^2: it lands on its edge and folds onto
  // itself within 60 steps, so the shares merge real contacts (asserted below), not empty lists.
  json scene = json::parse(testing::slurp(fs::path(TECIDO_SOURCE_DIR) / "bench" / "scenes" / "cloth_fold_128.json"));
  scene["cloth"]["rows"] = scene["cloth"]["cols"] = 40;
  scene["cloth"]["spacing"] = scene["cloth"]["spacing"].get<double>() * 128.0 / 40.0;
  scene["gravity"] = json::array({0, -400, 0});
  scene["steps"] = 60;
  for (const char* mode : {"discrete", "continuous"}) {
    scene["self_collision"] = std::string(mode) == "discrete"
                                  ? json{{"response", "edge3"}, {"strength", 0.001}, {"every", 1}}
                                  : json{{"detection", "continuous"}, {"response", "impulse"}, {"every", 1}};
    const fs::path file = dir / (std::string(mode) + ".json");
    testing::write_text(file, scene.dump());
    const auto one = run_cli("run '" + file.string() + "' --json --threads 1");
    ASSERT_EQ(one.code, 0) << mode << "\n" << one.err;
    EXPECT_GT(json::parse(one.out)["self_collision"]["pairs"].get<long long>(), 100) << one.out;
    for (const char* t : {"2", "3"}) {
      const auto r = run_cli("run '" + file.string() + "' --json --threads " + t);
      ASSERT_EQ(r.code, 0) << mode << "\n" << r.err;
      EXPECT_EQ(r.out, one.out) << mode << " --threads " << t;
    }
  }
  fs::remove_all(dir);
}

TEST(Determinism, RunOutResultJsonIsByteIdentical) {
  const auto dir = testing::temp_dir("det-run-out");
  const std::string scene = (fs::path(TECIDO_SOURCE_DIR) / "data" / "scenes" / "bounce_restitution.json").string();
  std::string bytes[2];
  for (int k = 0; k < 2; ++k) {
    const fs::path out = dir / ("out" + std::to_string(k));
    const auto r = run_cli("run '" + scene + "' --out '" + out.string() + "' --frame-every 1000");
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string text = testing::slurp(out / "result.json");
    EXPECT_NE(text.find("--out " + out.string() + " --frame-every 1000\""), std::string::npos) << text;
    bytes[k] = testing::mask_command_line(text);
  }
  EXPECT_FALSE(bytes[0].empty());
  EXPECT_EQ(bytes[0], bytes[1]);
  fs::remove_all(dir);
}

/// Runs `args` (with --out DIR appended) at --threads 1 and 2, twice each, and requires the
/// timing-free `file` to be identical in all four.
void expect_thread_independent(const std::string& name, const std::string& args, const std::string& file,
                               bool expect_timings) {
  const auto dir = testing::temp_dir("det-" + name);
  std::vector<std::string> outputs;
  for (int threads : {1, 2, 1, 2}) {
    const fs::path out = dir / ("t" + std::to_string(threads) + "-" + std::to_string(outputs.size()));
    const std::string tail = " --threads " + std::to_string(threads) + " --out " + out.string();
    const auto r = run_cli(args + " --threads " + std::to_string(threads) + " --out '" + out.string() + "'");
    ASSERT_TRUE(r.code == 0 || r.code == 1) << name << ": " << r.err;  // 1: a check failed, still a report
    ASSERT_TRUE(fs::exists(out / file)) << name << ": no " << file;
    int removed = 0;
    outputs.push_back(without_timings(out / file, args + tail, &removed));
    if (expect_timings) {
      EXPECT_GT(removed, 0) << name << ": no timing entry found; did the report format change?";
    }
  }
  EXPECT_EQ(outputs[0], outputs[2]) << name << ": two runs at 1 thread differ";
  EXPECT_EQ(outputs[1], outputs[3]) << name << ": two runs at 2 threads differ";
  EXPECT_EQ(outputs[0], outputs[1]) << name << ": 1 thread and 2 threads differ";
  fs::remove_all(dir);
}

TEST(Determinism, SuiteOrderReportIndependentOfThreads) {
  expect_thread_independent("order", "suite order --quick", "report.json", true);
}

TEST(Determinism, SuitePlaneReportIndependentOfThreads) {
  expect_thread_independent("plane", "suite plane --quick", "report.json", true);
}

TEST(Determinism, ExperimentSelfContactIndependentOfThreads) {
  // A spread of the 72 runs (both elasticities, all steps, the three winds and four responses
  // are interleaved in the index), enough for both threads to take several; the whole quick
  // experiment is a few seconds too long for a unit test.
  expect_thread_independent("self-contact", "experiment self-contact --quick --runs 0-3,30-33,68-71", "experiment.json",
                            false);
}

}  // namespace
}  // namespace tecido
