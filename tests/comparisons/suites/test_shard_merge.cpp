// `tecido experiment self-contact --shard i/n` and `tecido merge`: the merged shards are the
// unsharded run's files byte for byte; inconsistent shards exit 2 with one line. Also the
// progress bar (comparisons/io/progress.h). Quick runs of a few dt = 0.02 s cases keep it fast.
#include "tests/support/cli_runner.h"
#include "comparisons/io/progress.h"
#include "comparisons/suites/experiment_self_contact.h"
#include "comparisons/suites/merge.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <thread>

namespace tecido {
namespace {

using testing::run_cli;

std::string q(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

TEST(ShardMerge, MergedShardsEqualTheUnshardedRunByteForByte) {
  const auto dir = testing::temp_dir("shard-merge");
  const std::string base = "experiment self-contact --quick --threads 2 --runs 26,0-3,5";  // out of order on purpose
  const auto full = run_cli(base + " --out " + q(dir / "full"));
  const auto s0 = run_cli(base + " --shard 0/2 --out " + q(dir / "s0"));
  const auto s1 = run_cli(base + " --shard 1/2 --out " + q(dir / "s1"));
  ASSERT_EQ(full.code, 0) << full.err;
  ASSERT_EQ(s0.code, 0) << s0.err;
  ASSERT_EQ(s1.code, 0) << s1.err;
  EXPECT_TRUE(s0.err.empty()) << "no progress bar when stderr is not a terminal: " << s0.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "s0" / "experiment.md"));

  const auto j0 = nlohmann::json::parse(testing::slurp(dir / "s0" / "experiment.json"));
  const auto j1 = nlohmann::json::parse(testing::slurp(dir / "s1" / "experiment.json"));
  EXPECT_EQ(j0["shard"], nlohmann::json::array({0, 2}));
  EXPECT_EQ(j1["shard"], nlohmann::json::array({1, 2}));
  EXPECT_EQ(j0["selection"], nlohmann::json::array({26, 0, 1, 2, 3, 5}));
  std::vector<int> idx0, idx1;
  for (const auto& r : j0["runs"]) idx0.push_back(r["index"].get<int>());
  for (const auto& r : j1["runs"]) idx1.push_back(r["index"].get<int>());
  EXPECT_EQ(idx0, (std::vector<int>{26, 0, 2}));
  EXPECT_EQ(idx1, (std::vector<int>{1, 3, 5}));

  // Shards in any order on the command line.
  const auto m = run_cli("merge " + q(dir / "s1") + " " + q(dir / "s0") + " --out " + q(dir / "merged"));
  ASSERT_EQ(m.code, 0) << m.err;
  const std::string want_json = testing::slurp(dir / "full" / "experiment.json");
  ASSERT_FALSE(want_json.empty());
  EXPECT_EQ(testing::slurp(dir / "merged" / "experiment.json"), want_json);
  EXPECT_EQ(testing::slurp(dir / "merged" / "experiment.md"), testing::slurp(dir / "full" / "experiment.md"));

  // The real shards, inconsistently combined.
  for (const std::string& args : {"merge " + q(dir / "s0") + " " + q(dir / "s0") + " " + q(dir / "s1"),  // duplicate
                                  "merge " + q(dir / "s0"),                                               // missing
                                  "merge " + q(dir / "s0") + " " + q(dir / "full"),                       // not a shard
                                  "merge " + q(dir / "nonexistent")}) {
    const auto r = run_cli(args + " --out " + q(dir / "bad"));
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "bad"));
  std::filesystem::remove_all(dir);
}

/// Synthetic shard files (no simulation): the runs' results are made up.
struct FakeShards {
  std::filesystem::path dir;
  suites::SelfContactOptions opt;
  std::vector<suites::SelfContactResult> results;  // for the selection, in its order

  explicit FakeShards(const std::string& name) : dir(testing::temp_dir(name)) {
    opt.scene_path = "scene.json";
    opt.seed_table_path = std::string(TECIDO_SOURCE_DIR) + "/data/seed_tables/self_contact_share.json";
    opt.simulated_time = 2.0;
    opt.quick = true;
    opt.runs = {7, 2, 3, 4, 10};
    const auto all = suites::self_contact_runs();
    for (int i : opt.runs) {
      suites::SelfContactResult r;
      r.run = all[i];
      r.frames = 100;
      r.contact_frames = i;
      r.share = i / 100.0;
      r.pairs = 3 * i;
      r.max_pairs = i;
      if (i == 3) {
        r.status = "unstable";
        r.unstable_at_step = 42;
      }
      results.push_back(r);
    }
  }
  /// Writes shard i of n (optionally dropping or adding a run) and returns its directory.
  std::string write(int i, int n, int drop = -1, int add = -1) {
    suites::SelfContactOptions o = opt;
    o.shard_index = i;
    o.shard_count = n;
    std::vector<suites::SelfContactResult> mine;
    for (const auto& r : results)
      if ((r.run.index % n == i && r.run.index != drop) || r.run.index == add) mine.push_back(r);
    const auto d = dir / ("s" + std::to_string(i) + "of" + std::to_string(n) + "-" + std::to_string(drop) + "-" +
                          std::to_string(add));
    std::filesystem::create_directories(d);
    testing::write_text(d / "experiment.json", suites::self_contact_shard_json(mine, o));
    return q(d);
  }
};

TEST(ShardMerge, SyntheticShardsMergeExactly) {
  FakeShards f("shard-fake");
  const auto m = run_cli("merge " + f.write(2, 3) + " " + f.write(0, 3) + " " + f.write(1, 3) + " --out " + q(f.dir / "m"));
  ASSERT_EQ(m.code, 0) << m.err;
  EXPECT_EQ(testing::slurp(f.dir / "m" / "experiment.json"), suites::self_contact_json(f.results, f.opt));
  const auto seed = io::read_json_file(f.opt.seed_table_path);
  EXPECT_EQ(testing::slurp(f.dir / "m" / "experiment.md"), suites::self_contact_markdown(f.results, seed, f.opt));
  std::filesystem::remove_all(f.dir);
}

TEST(ShardMerge, InconsistentShardsExitTwo) {
  FakeShards f("shard-bad");
  const std::string out = " --out " + q(f.dir / "never");
  const std::string s0 = f.write(0, 2), s1 = f.write(1, 2);
  struct Case {
    std::string args, says;
  };
  const Case cases[] = {
      {s0 + " " + s1 + " " + s0, "given twice"},
      {s1, "shard 0/2 is missing"},
      {s0 + " " + f.write(1, 3), "does not belong"},
      {s0 + " " + f.write(1, 2, 3), "run 3 is missing"},
      {s0 + " " + f.write(1, 2, -1, 2), "belongs to shard 0/2"},
  };
  for (const auto& c : cases) {
    const auto r = run_cli("merge " + c.args + out);
    EXPECT_EQ(r.code, 2) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  // Other settings in one shard.
  f.opt.strength = 0.5;
  const auto r = run_cli("merge " + s0 + " " + f.write(1, 2) + out);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("other settings"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(f.dir / "never"));
  std::filesystem::remove_all(f.dir);
}

TEST(ShardMerge, BadShardOptionExitsTwo) {
  for (const char* shard : {"2/2", "x", "1/0", "-1/2", "1/2/3", "1"}) {
    const auto r = run_cli(std::string("experiment self-contact --quick --runs 0 --shard ") + shard +
                           " --out /tmp/tecido-never-written-shard");
    EXPECT_EQ(r.code, 2) << shard << ": " << r.err;
  }
  const auto dup = run_cli("experiment self-contact --quick --runs 0,0 --shard 0/2 --out /tmp/tecido-never-written-shard");
  EXPECT_EQ(dup.code, 2) << dup.err;
  EXPECT_FALSE(std::filesystem::exists("/tmp/tecido-never-written-shard/experiment.json"));
}

TEST(Progress, DrawsOnlyWhenEnabledAndEndsTheLine) {
  EXPECT_EQ(io::Progress::line("sweep", 3, 12, 2.0), "sweep [#######.......................] 3/12  1.50/s  ETA 0:06");
  EXPECT_EQ(io::Progress::line("x", 0, 4, 0.0), "x [..............................] 0/4  0.00/s  ETA --:--");
  EXPECT_EQ(io::Progress::line("x", 4, 4, 1.0).find("ETA 0:00") != std::string::npos, true);
  std::ostringstream on, off;
  {
    io::Progress p(4, "on", on, true), silent(4, "off", off, false);
    std::vector<std::thread> ts;
    for (int t = 0; t < 4; ++t) ts.emplace_back([&] { p.tick(); silent.tick(); });
    for (auto& t : ts) t.join();
  }
  EXPECT_TRUE(off.str().empty());
  const std::string s = on.str();
  ASSERT_FALSE(s.empty());
  EXPECT_EQ(s.front(), '\r');
  EXPECT_EQ(s.back(), '\n');
  EXPECT_NE(s.find("4/4"), std::string::npos) << s;
  EXPECT_EQ(std::count(s.begin(), s.end(), '\n'), 1);
}

}  // namespace
}  // namespace tecido
