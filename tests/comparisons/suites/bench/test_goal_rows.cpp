// The bench suite's goal rows (comparisons/suites/bench/goal_rows.*) from hand-made benchmark rows:
// each value counted by hand, met or not against its target (at most, or at least for a
// speed-up), "not measured" when a row is missing, and report.json's machine-readable shape.
#include "comparisons/suites/bench/goal_rows.h"

#include "tests/comparisons/suites/bench/planted_rows.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::suites::bench {
namespace {

BenchRow timed(const std::string& name, double cpu_ns, double wall_ns, io::Json counters = io::Json::object()) {
  BenchRow r = row(name, cpu_ns);
  r.real_ns_per_iter = wall_ns;
  r.counters = std::move(counters);
  return r;
}

/// Issue 24's rows: ratios chosen so that each can be counted by hand.
std::vector<BenchRow> issue24_rows() {
  std::vector<BenchRow> rows = {
      row("BM_ContinuousSelfCollision/core/128", 30e6), row("BM_ContinuousSelfCollision/discrete/128", 6e6),
      row("BM_ContinuousSelfCollision/confirmed/128", 12e6), row("BM_SelfCollision/core-flat/256", 16e6),
      timed("process/selfcollide/discrete/128", 1e9, 1.1e9),
      timed("process/selfcollide/continuous/threads:1/128", 2.5e9, 3e9, {{"same_answer", 1}}),
      timed("process/selfcollide/continuous/threads:2/128", 2.6e9, 2e9, {{"same_answer", 0}}),
      timed("BM_CCD/core/vertex-face", 0, 0, {{"false_negatives", 0}, {"false_positive_share", 0.02}}),
      timed("BM_ContinuousSelfCollision/threads:1/256", 100e6, 100e6), timed("BM_ContinuousSelfCollision/threads:2/256", 100e6, 50e6),
      timed("BM_SelfCollisionLongRun/experiment/discrete", 1, 1, {{"reuse_us", 100}, {"scratch_us", 400}}),
      timed("BM_SelfCollisionLongRun/experiment/continuous", 1, 1, {{"reuse_us", 500}, {"scratch_us", 400}})};
  rows.push_back(row("BM_CCD/fcl/vertex-face", 0));
  rows[7].ns_per_item = 100;
  rows.back().ns_per_item = 250;
  return rows;
}

const GoalRow& goal(const std::vector<GoalRow>& goals, const std::string& id) {
  for (const GoalRow& g : goals)
    if (g.id == id) return g;
  throw std::runtime_error("no goal " + id);
}

TEST(BenchGoalRows, EveryGoalOfIssue24ComputedFromItsRows) {
  const auto goals = goal_rows(issue24_rows(), Settings{}, Goals{});
  const auto check = [&goals](const std::string& id, double value, bool met) {
    const GoalRow& g = goal(goals, id);
    EXPECT_NEAR(g.value, value, 1e-12) << id;
    EXPECT_TRUE(g.measured()) << id;
    EXPECT_EQ(g.met(), met) << id;
  };
  check("continuous_128_over_discrete", 5.0, false);         // 30 / 6 > 3
  check("continuous_exact_128_over_discrete", 2.0, true);    // 12 / 6
  check("selfcollision_flat_256_ms", 16.0, false);           // > 15 ms
  check("selfcollide_process_128_over_discrete", 2.5, true);  // CPU 2.5 s / 1 s
  check("threads_selfcollide_process_128_speedup", 1.5, false);  // wall 3 s / 2 s < 1.7
  check("threads_answers_differing", 1.0, false);            // threads:2's same_answer is 0
  check("ccd_vertex_face_core_over_fcl", 0.4, true);         // 100 / 250 ns per query
  check("ccd_vertex_face_false_negatives", 0.0, true);
  check("ccd_vertex_face_false_positive_share", 0.02, false);  // > 1%
  check("threads_continuous_256_speedup", 2.0, true);        // wall 100 / 50 ms (CPU equal: not used)
  check("long_run_experiment_discrete_kept_over_scratch", 0.25, true);
  check("long_run_experiment_continuous_kept_over_scratch", 1.25, false);
  EXPECT_TRUE(goal(goals, "threads_continuous_256_speedup").at_least);
  EXPECT_FALSE(goal(goals, "continuous_128_over_discrete").at_least);
  for (const char* id : {"threads_discrete_256_speedup", "ccd_edge_edge_core_over_fcl", "selfcollision_256_ms"}) {
    EXPECT_FALSE(goal(goals, id).measured()) << id;
    EXPECT_FALSE(goal(goals, id).met()) << id << ": a goal not measured is not met";
  }
  EXPECT_THROW(goal(goals, "long_run_fold128_discrete_kept_over_scratch"), std::runtime_error)
      << "the minutes-long fold128 run has a row only when it ran";
  std::vector<BenchRow> with_full = issue24_rows();
  with_full.push_back(timed("BM_SelfCollisionLongRun/fold128/discrete", 1, 1, {{"reuse_us", 3}, {"scratch_us", 6}}));
  EXPECT_DOUBLE_EQ(goal(goal_rows(with_full, Settings{}, Goals{}), "long_run_fold128_discrete_kept_over_scratch").value, 0.5);
}

TEST(BenchGoalRows, ReportJsonHasIdValueTargetComparisonAndMet) {
  const io::Json j = goals_json(goal_rows(issue24_rows(), Settings{}, Goals{}));
  ASSERT_TRUE(j.is_array());
  bool seen_speedup = false, seen_missing = false;
  for (const io::Json& g : j) {
    for (const char* key : {"id", "what", "value", "target", "comparison", "unit", "met", "from"})
      EXPECT_TRUE(g.contains(key)) << key << " in " << g.dump();
    if (g["id"] == "threads_continuous_256_speedup") {
      seen_speedup = true;
      EXPECT_EQ(g["comparison"], "at_least");
      EXPECT_DOUBLE_EQ(g["value"].get<double>(), 2.0);
      EXPECT_DOUBLE_EQ(g["target"].get<double>(), 1.7);
      EXPECT_EQ(g["met"], true);
    }
    if (g["id"] == "threads_discrete_256_speedup") {
      seen_missing = true;
      EXPECT_TRUE(g["value"].is_null());
      EXPECT_TRUE(g["met"].is_null()) << "not measured: neither met nor not met";
    }
  }
  EXPECT_TRUE(seen_speedup && seen_missing);
}

}  // namespace
}  // namespace tecido::suites::bench
