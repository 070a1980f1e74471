// `tecido experiment forced-contact` end to end (--quick): bad options exit 2 with one line and
// write nothing, shards merged equal the unsharded run byte for byte, the result does not depend
// on the thread count, --frames writes viewable frames, and the report holds every claim.
#include "tests/support/cli_runner.h"
#include "tests/support/command_line_mask.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace tecido {
namespace {

using testing::run_cli;

std::string quoted(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

TEST(ForcedContactExperiment, BadOptionsExit2WithOneLine) {
  const auto dir = testing::temp_dir("forced-bad");
  for (const std::string& args : {std::string("experiment forced-contact --quick --calibrate"),
                                  std::string("experiment forced-contact --quick --detector core"),
                                  std::string("experiment forced-contact --quick --seeds 0"),
                                  std::string("experiment forced-contact --quick --shard 2/2"),
                                  std::string("experiment forced-contact --quick --max-work 10"),
                                  std::string("experiment self-contact --quick --frames"),
                                  std::string("experiment forced-contacts --quick")}) {
    const auto r = run_cli(args + " --out " + quoted(dir / "out"));
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out" / "experiment.json")) << args;
  }
  std::filesystem::remove_all(dir);
}

TEST(ForcedContactExperiment, ShardsMergeToTheUnshardedRunAndThreadsChangeNothing) {
  const auto dir = testing::temp_dir("forced-shards");
  const std::string base = "experiment forced-contact --quick";
  const auto full = run_cli(base + " --threads 2 --frames --out " + quoted(dir / "full"));
  const auto one = run_cli(base + " --threads 1 --out " + quoted(dir / "one"));
  const auto s0 = run_cli(base + " --threads 2 --shard 0/2 --out " + quoted(dir / "s0"));
  const auto s1 = run_cli(base + " --threads 1 --shard 1/2 --out " + quoted(dir / "s1"));
  ASSERT_EQ(full.code, 0) << full.err;
  ASSERT_EQ(one.code, 0) << one.err;
  ASSERT_EQ(s0.code, 0) << s0.err;
  ASSERT_EQ(s1.code, 0) << s1.err;
  const auto m = run_cli("merge " + quoted(dir / "s1") + " " + quoted(dir / "s0") + " --out " + quoted(dir / "merged"));
  ASSERT_EQ(m.code, 0) << m.err;
  const std::string json = testing::mask_command_line(testing::slurp(dir / "full" / "experiment.json"));
  EXPECT_EQ(testing::mask_command_line(testing::slurp(dir / "merged" / "experiment.json")), json);
  EXPECT_EQ(testing::mask_command_line(testing::slurp(dir / "one" / "experiment.json")), json);
  EXPECT_EQ(testing::slurp(dir / "merged" / "experiment.md"), testing::slurp(dir / "full" / "experiment.md"));
  EXPECT_EQ(testing::slurp(dir / "one" / "experiment.md"), testing::slurp(dir / "full" / "experiment.md"));

  const auto j = nlohmann::json::parse(testing::slurp(dir / "full" / "experiment.json"));
  EXPECT_EQ(j["experiment"], "forced-contact");
  ASSERT_EQ(j["claims"].size(), 4u);
  for (const auto& c : j["claims"]) {
    const std::string v = c["verdict"];
    EXPECT_TRUE(v == "reproduced" || v == "not reproduced" || v == "inconclusive") << v;
    EXPECT_FALSE(c["rule"].get<std::string>().empty());
  }
  EXPECT_EQ(j["cells"].size(), 2u * 7u);  // quick: 2 holds x 7 responses
  EXPECT_EQ(j["runs"].size(), 2u * 7u * 2u);
  // Every run of the quick plan is forced: the grips hold the layers through each other.
  for (const auto& run : j["runs"]) EXPECT_GT(run["held_pairs"].get<long long>(), 0) << run["response"];
  // Frames of run 0 for each (response, hold), OBJ.
  EXPECT_TRUE(std::filesystem::exists(dir / "full" / "frames" / "impulse-hold0.03" / "frame_000005.obj"));
  EXPECT_TRUE(std::filesystem::exists(dir / "full" / "frames" / "gia-hold0.3"));
  // Mixing experiments' shards is refused.
  const auto mixed = run_cli("merge " + quoted(dir / "s0") + " --seed-table x --out " + quoted(dir / "bad"));
  EXPECT_EQ(mixed.code, 2) << mixed.err;
  const auto lone = run_cli("merge " + quoted(dir / "s0") + " --out " + quoted(dir / "bad"));
  EXPECT_EQ(lone.code, 2) << lone.err;
  EXPECT_EQ(std::count(lone.err.begin(), lone.err.end(), '\n'), 1) << lone.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad" / "experiment.json"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido
