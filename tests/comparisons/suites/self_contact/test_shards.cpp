// `tecido experiment self-contact --shard i/n` and `tecido merge`: merged shards give the unsharded
// run's files byte for byte (a few quick cells, no timing cases); made-up results of a plan,
// written as shards, merge into exactly what assembling them directly gives; inconsistent shards
// exit 2 with one line.
#include "comparisons/io/source_dir.h"
#include "tests/support/cli_runner.h"
#include "tests/support/command_line_mask.h"
#include "comparisons/suites/self_contact/shards.h"
#include "comparisons/suites/shard_file.h"
#include "comparisons/suites/suite_shard.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <algorithm>

namespace tecido {
namespace {

namespace sc = suites::self_contact;
using testing::run_cli;

std::string quoted_path(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

TEST(ExperimentShards, MergedShardsEqualTheUnshardedRunByteForByte) {
  const auto dir = testing::temp_dir("exp-shards");
  const std::string base = "experiment self-contact --quick --threads 2 --runs 26,0-3,5";  // out of order on purpose
  const auto full = run_cli(base + " --out " + quoted_path(dir / "full"));
  const auto s0 = run_cli(base + " --shard 0/2 --out " + quoted_path(dir / "s0"));
  const auto s1 = run_cli(base + " --shard 1/2 --out " + quoted_path(dir / "s1"));
  ASSERT_EQ(full.code, 0) << full.err;
  ASSERT_EQ(s0.code, 0) << s0.err;
  ASSERT_EQ(s1.code, 0) << s1.err;
  EXPECT_TRUE(s0.err.empty()) << "no progress bar when stderr is not a terminal: " << s0.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "s0" / "experiment.md"));
  // A cell's two seeds are consecutive cases, so they land on different shards.
  const auto j0 = nlohmann::json::parse(testing::slurp(dir / "s0" / "experiment.json"));
  EXPECT_EQ(j0["shard"], nlohmann::json::array({0, 2}));
  ASSERT_EQ(j0["results"].size(), 6u);
  EXPECT_EQ(j0["results"][0]["result"]["case"][2], 26);
  EXPECT_EQ(j0["results"][0]["result"]["case"][3], 0);
  const auto m = run_cli("merge " + quoted_path(dir / "s1") + " " + quoted_path(dir / "s0") + " --out " + quoted_path(dir / "merged"));
  ASSERT_EQ(m.code, 0) << m.err;
  // Byte for byte but for the command line each records (the merge's, the run's).
  EXPECT_EQ(testing::mask_command_line(testing::slurp(dir / "merged" / "experiment.json")),
            testing::mask_command_line(testing::slurp(dir / "full" / "experiment.json")));
  EXPECT_EQ(testing::slurp(dir / "merged" / "experiment.md"), testing::slurp(dir / "full" / "experiment.md"));
  for (const std::string& args : {"merge " + quoted_path(dir / "s0") + " " + quoted_path(dir / "s0") + " " + quoted_path(dir / "s1"),
                                  "merge " + quoted_path(dir / "s0"), "merge " + quoted_path(dir / "s0") + " " + quoted_path(dir / "full"),
                                  "merge " + quoted_path(dir / "nonexistent")}) {
    const auto r = run_cli(args + " --out " + quoted_path(dir / "bad"));
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "bad"));
  std::filesystem::remove_all(dir);
}

/// A plan of a few cells and made-up results for its cases (no simulation).
struct FakeRun {
  std::filesystem::path dir;
  sc::Options opt;
  std::shared_ptr<const sc::Plan> plan;
  std::vector<nlohmann::json> results;

  explicit FakeRun(const std::string& name) : dir(testing::temp_dir(name)) {
    const std::string data = std::string(TECIDO_SOURCE_DIR) + "/data";
    opt.scene_path = data + "/scenes/seed_fig21_self_contact.json";
    opt.seed_table_path = data + "/seed_tables/self_contact_share.json";
    opt.calibration_path = data + "/seed_tables/self_contact_calibration.json";
    opt.quick = true;
    opt.seeds = 3;
    opt.cells = {7, 4, 5, 6, 10};
    plan = std::make_shared<const sc::Plan>(sc::make_plan(opt));
    for (std::size_t k = 0; k < plan->cases.size(); ++k) {
      const sc::CaseSpec& c = plan->cases[k];
      sc::RunResult r;
      r.counts.push_back({100, (c.cell * 7 + c.seed * 3) % 40, c.cell, 2});
      if (k == 4) r.status = "unstable", r.unstable_at_step = 42;
      nlohmann::json j = sc::run_json(r, sc::CellGrid::key(c.cell).mode == 0);
      j["case"] = {static_cast<int>(c.kind), c.variant, c.cell, c.seed, c.grid};
      results.push_back(k == 7 ? nlohmann::json{{"error", "case 7 threw: planted"}} : j);
    }
  }
  /// Writes shard i of n, optionally dropping or duplicating a case, and returns its directory.
  std::string write(int i, int n, int drop = -1, int add = -1) {
    sc::Options o = opt;
    o.shard_index = i;
    o.shard_count = n;
    sc::Plan p = *plan;
    p.opt = o;
    std::vector<std::size_t> idx;
    std::vector<nlohmann::json> res;
    for (std::size_t k = 0; k < results.size(); ++k)
      if ((static_cast<int>(k) % n == i && static_cast<int>(k) != drop) || static_cast<int>(k) == add) idx.push_back(k), res.push_back(results[k]);
    const auto d = dir / ("s" + std::to_string(i) + "of" + std::to_string(n) + "-" + std::to_string(drop) + "-" + std::to_string(add));
    std::filesystem::create_directories(d);
    testing::write_text(d / "experiment.json", sc::shard_json(p, idx, res));
    return quoted_path(d);
  }
};

TEST(ExperimentShards, MadeUpResultsMergeExactlyAndErrorsAreKept) {
  FakeRun f("exp-fake");
  const auto m = run_cli("merge " + f.write(2, 3) + " " + f.write(0, 3) + " " + f.write(1, 3) + " --out " + quoted_path(f.dir / "m"));
  ASSERT_EQ(m.code, 0) << m.err;
  sc::Options o = f.opt;
  o.out_dir = (f.dir / "direct").string();
  const sc::Outputs want = sc::assemble(sc::make_plan(o), f.results);
  EXPECT_EQ(testing::mask_command_line(testing::slurp(f.dir / "m" / "experiment.json")),
            testing::mask_command_line(want.files[0].second));
  const auto j = nlohmann::json::parse(want.files[0].second);
  ASSERT_EQ(j["errors"].size(), 1u);
  EXPECT_EQ(j["errors"][0], "case 7 threw: planted");
  int errors = 0;
  for (const auto& r : j["runs"]) errors += r.contains("error");
  EXPECT_EQ(errors, 1);  // reported, never dropped
  std::filesystem::remove_all(f.dir);
}

TEST(ExperimentShards, InconsistentShardsExitTwo) {
  FakeRun f("exp-bad");
  const std::string out = " --out " + quoted_path(f.dir / "never");
  const std::string s0 = f.write(0, 2), s1 = f.write(1, 2);
  struct Case {
    std::string args, says;
  };
  const Case cases[] = {
      {s0 + " " + s1 + " " + s0, "given twice"},
      {s1, "shard 0/2 is missing"},
      {s0 + " " + f.write(1, 3), "does not belong"},
      {s0 + " " + f.write(1, 2, 3), "case 3 is missing"},
      {s0 + " " + f.write(1, 2, -1, 2), "belongs to shard 0/2"},
  };
  for (const auto& c : cases) {
    const auto r = run_cli("merge " + c.args + out);
    EXPECT_EQ(r.code, 2) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  f.opt.seeds = 2;  // other settings in one shard
  f.plan = std::make_shared<const sc::Plan>(sc::make_plan(f.opt));
  const auto r = run_cli("merge " + s0 + " " + f.write(1, 2) + out);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("other settings"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(f.dir / "never"));
  std::filesystem::remove_all(f.dir);
}

TEST(ExperimentShards, BadShardOptionExitsTwo) {
  for (const char* shard : {"2/2", "x", "1/0", "-1/2", "1/2/3", "1"}) {
    const auto r = run_cli(std::string("experiment self-contact --quick --runs 0 --shard ") + shard +
                           " --out /tmp/tecido-never-written-shard");
    EXPECT_EQ(r.code, 2) << shard << ": " << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists("/tmp/tecido-never-written-shard/experiment.json"));
}

}  // namespace
}  // namespace tecido
