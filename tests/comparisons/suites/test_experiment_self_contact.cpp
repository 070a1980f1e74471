// `tecido experiment self-contact`: the run grid, the output contract, and bit-identical
// output at 1 and 2 threads (quick runs, a reduced run set, so it stays fast).
#include "tests/support/cli_runner.h"
#include "comparisons/suites/experiment_self_contact.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

namespace tecido {
namespace {

using testing::run_cli;

TEST(ExperimentSelfContact, SeventyTwoRunsInTheDocumentedOrder) {
  const auto runs = suites::self_contact_runs();
  ASSERT_EQ(runs.size(), 72u);
  const double dts[3] = {0.02, 0.01, 0.005}, winds[3] = {0.09, 0.1, 0.11};
  for (int i = 0; i < 72; ++i) {
    EXPECT_EQ(runs[i].index, i);
    EXPECT_EQ(runs[i].mode, i % 4);
    EXPECT_EQ(runs[i].elasticity, (i / 4) % 2 == 0 ? 0.9 : 0.5);
    EXPECT_EQ(runs[i].dt, dts[(i / 8) % 3]);
    EXPECT_EQ(runs[i].wind, winds[i / 24]);
  }
}

TEST(ExperimentSelfContact, SceneIsPatchedAsDocumented) {
  const auto base = io::read_json_file(std::string(TECIDO_SOURCE_DIR) + "/data/scenes/seed_fig21_self_contact.json");
  suites::SelfContactOptions opt;
  const auto run = suites::self_contact_runs()[2 * 24 + 1 * 8 + 1 * 4 + 2];  // wind 0.11, dt 0.01, e 0.5, mode 2
  const auto doc = suites::self_contact_scene(base, run, opt, "base.json");
  EXPECT_EQ(doc["dt"].get<double>(), 0.01);
  EXPECT_EQ(doc["steps"].get<long long>(), 1000);
  const auto& f = doc["wind"]["force"];
  EXPECT_NEAR(std::hypot(f[0].get<double>(), f[1].get<double>(), f[2].get<double>()), 0.11, 1e-15);
  EXPECT_EQ(doc["cloth"]["stiffness_b"].get<double>(), base["cloth"]["stiffness_b"].get<double>() * 0.5);
  EXPECT_EQ(doc["cloth"]["stiffness_a"].get<double>(), base["cloth"]["stiffness_a"].get<double>() * 0.5);
  EXPECT_EQ(doc["self_collision"]["response"], "edge2");
  opt.elasticity_as = "restitution";
  const auto doc2 = suites::self_contact_scene(base, run, opt, "base.json");
  EXPECT_EQ(doc2["cloth"]["stiffness_b"], base["cloth"]["stiffness_b"]);
  EXPECT_EQ(doc2["cloth"]["elasticity"].get<double>(), 0.5);
}

TEST(ExperimentSelfContact, OutputIsBitIdenticalAtOneAndTwoThreads) {
  const auto dir = testing::temp_dir("experiment");
  const std::string runs = "0-3,13,26,47,70";
  const auto a = run_cli("experiment self-contact --quick --runs " + runs + " --threads 1 --out '" + (dir / "t1").string() + "'");
  const auto b = run_cli("experiment self-contact --quick --runs " + runs + " --threads 2 --out '" + (dir / "t2").string() + "'");
  ASSERT_EQ(a.code, 0) << a.err;
  ASSERT_EQ(b.code, 0) << b.err;
  const std::string j1 = testing::slurp(dir / "t1" / "experiment.json"), j2 = testing::slurp(dir / "t2" / "experiment.json");
  EXPECT_EQ(j1, j2);
  EXPECT_EQ(testing::slurp(dir / "t1" / "experiment.md"), testing::slurp(dir / "t2" / "experiment.md"));
  const auto j = nlohmann::json::parse(j1);
  ASSERT_EQ(j["runs"].size(), 8u);
  EXPECT_EQ(j["simulated_time"].get<double>(), 2.0);
  for (const auto& r : j["runs"]) {
    for (const char* key : {"elasticity", "dt", "wind", "mode", "frames", "contact_frames", "share"})
      EXPECT_TRUE(r.contains(key)) << key;
    EXPECT_EQ(r["frames"].get<long long>(), std::llround(2.0 / r["dt"].get<double>()));
    EXPECT_LE(r["contact_frames"].get<long long>(), r["frames"].get<long long>());
    EXPECT_EQ(r["share"].get<double>(),
              static_cast<double>(r["contact_frames"].get<long long>()) / r["frames"].get<long long>());
  }
  EXPECT_EQ(j["runs"][0]["mode"], "none");
  EXPECT_EQ(j["runs"][3]["mode"], 3);
  std::filesystem::remove_all(dir);
}

TEST(ExperimentSelfContact, BadUsageExitsTwo) {
  for (const char* args : {"experiment nope", "experiment self-contact --runs 72 --quick", "experiment self-contact --runs x-3",
                           "experiment self-contact --elasticity-as nothing", "experiment self-contact --strength -1 --quick",
                           "experiment self-contact --scene /nonexistent.json --quick"}) {
    const auto r = run_cli(std::string(args) + " --out /tmp/tecido-never-written");
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_FALSE(r.err.empty()) << args;
  }
  EXPECT_FALSE(std::filesystem::exists("/tmp/tecido-never-written/experiment.json"));
}

}  // namespace
}  // namespace tecido
