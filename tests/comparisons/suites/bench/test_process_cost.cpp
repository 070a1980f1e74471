// The timed `selfcollide` processes of the bench suite (comparisons/suites/bench/process_cost.*),
// with a stand-in script in tecido's place: the frames written (and read back to the same doubles),
// one row per command named as the goals expect, the answers compared between thread counts, a
// failure reported.
#include "comparisons/suites/bench/process_cost.h"

#include "comparisons/io/obj_mesh.h"
#include "comparisons/suites/bench/folding_cloth.h"
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace tecido::suites::bench {
namespace {

/// Prints its --threads value when `differ` is set (the answers then differ between thread counts).
std::string fake(bool differ) {
  return std::string("#!/bin/sh\nt=1\nwhile [ $# -gt 0 ]; do [ \"$1\" = --threads ] && t=$2; shift; done\n") +
         (differ ? "echo \"{\\\"t\\\":$t}\"\n" : "echo '{}'\n");
}

TEST(BenchProcessCost, OneRowPerCommandAndTheAnswersCompared) {
  const auto dir = testing::temp_dir("bench-process");
  const auto bin = dir / "fake-tecido";
  testing::write_text(bin, fake(false));
  std::filesystem::permissions(bin, std::filesystem::perms::owner_all);
  const ProcessRun run = time_selfcollide(bin.string(), (dir / "out").string(), 4, 2, {1, 2});
  ASSERT_TRUE(run.error.empty()) << run.error;
  ASSERT_EQ(run.rows.size(), 3u);
  EXPECT_EQ(run.rows[0].name, "process/selfcollide/discrete/4");
  EXPECT_EQ(run.rows[1].name, "process/selfcollide/continuous/threads:1/4");
  EXPECT_EQ(run.rows[2].name, "process/selfcollide/continuous/threads:2/4");
  EXPECT_EQ(run.rows[2].counters["same_answer"], 1);
  EXPECT_EQ(run.rows[0].counters["triangles"], 18) << "2 (4 - 1)^2";
  EXPECT_FALSE(run.rows[0].counters.contains("same_answer"));
  for (const BenchRow& r : run.rows) EXPECT_GT(r.real_ns_per_iter, 0) << r.name;
  EXPECT_EQ(run.commands[2], "build/bin/tecido selfcollide --mesh " + (dir / "out" / "fold_4_t0.obj").string() + " --to " +
                                 (dir / "out" / "fold_4_t1.obj").string() + " --threads 2 --json");
  const FoldingStep step = folding_cloth_step(4);
  const io::ObjMesh m0 = io::load_obj_mesh((dir / "out" / "fold_4_t0.obj").string());
  EXPECT_EQ(m0.vertices, step.x0) << "17 digits: the doubles round-trip";
  EXPECT_EQ(m0.triangles, step.triangles);
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "continuous-1.out")) << "outputs removed once compared";

  testing::write_text(bin, fake(true));
  const ProcessRun differ = time_selfcollide(bin.string(), (dir / "out").string(), 4, 1, {1, 2});
  ASSERT_TRUE(differ.error.empty()) << differ.error;
  EXPECT_EQ(differ.rows[1].counters["same_answer"], 1) << "the first thread count is the reference";
  EXPECT_EQ(differ.rows[2].counters["same_answer"], 0);

  testing::write_text(bin, "#!/bin/sh\nexit 2\n");
  const ProcessRun bad = time_selfcollide(bin.string(), (dir / "out").string(), 4, 1, {1});
  EXPECT_NE(bad.error.find("failed; see `bench/selfcollide.stderr`"), std::string::npos) << bad.error;
  EXPECT_TRUE(bad.rows.empty());
  std::filesystem::remove_all(dir);
}

TEST(BenchProcessCost, PathsWithQuotesAndSpacesReachTheCommandIntact) {
  const auto dir = testing::temp_dir("bench-process-quoted") / "it's a $dir";
  std::filesystem::create_directories(dir);
  const auto bin = dir / "fake tecido";
  testing::write_text(bin, fake(true));
  std::filesystem::permissions(bin, std::filesystem::perms::owner_all);
  const ProcessRun run = time_selfcollide(bin.string(), (dir / "out").string(), 3, 1, {1, 2});
  ASSERT_TRUE(run.error.empty()) << run.error;
  ASSERT_EQ(run.rows.size(), 3u);
  EXPECT_EQ(run.rows[2].counters["same_answer"], 0) << "the fake saw --threads 2: the arguments arrived as words";
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "fold_3_t1.obj"));
  const std::string quoted_out = "'" + dir.parent_path().string() + "/it'\\''s a $dir/out/";
  EXPECT_EQ(run.commands[1], "build/bin/tecido selfcollide --mesh " + quoted_out + "fold_3_t0.obj' --to " + quoted_out +
                                 "fold_3_t1.obj' --threads 1 --json");
  std::filesystem::remove_all(dir.parent_path());
}

}  // namespace
}  // namespace tecido::suites::bench
