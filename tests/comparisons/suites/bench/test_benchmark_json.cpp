// Google Benchmark's JSON read by the bench suite (comparisons/suites/bench/benchmark_json.*):
// iteration rows, or the median where a benchmark was repeated; CPU time in nanoseconds whatever the unit, user counters and labels kept.
#include "comparisons/suites/bench/benchmark_json.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::suites::bench {
namespace {

const char* kDoc = R"({"context":{"num_cpus":2},"benchmarks":[
  {"name":"BM_TriTri/core","run_name":"BM_TriTri/core","run_type":"iteration","iterations":10,
   "real_time":40.0,"cpu_time":35.0,"time_unit":"us","items_per_second":2.5e7},
  {"name":"BM_ClothStep/core-symplectic/16","run_type":"iteration","real_time":9.0,"cpu_time":8.0,
   "time_unit":"ms","springs":1000,"nodes":256,"label":"avx512"},
  {"name":"BM_ClothStep/core-symplectic/16_mean","run_name":"BM_ClothStep/core-symplectic/16","run_type":"aggregate",
   "aggregate_name":"mean","real_time":1,"cpu_time":1,"time_unit":"ns"},
  {"name":"BM_Broken","run_type":"iteration","error_occurred":true,"error_message":"no","real_time":0,"cpu_time":0}
]})";

TEST(BenchmarkJson, IterationRowsInNanosecondsOfCpuTime) {
  const auto rows = parse_benchmark_json(io::Json::parse(kDoc));
  ASSERT_EQ(rows.size(), 2u) << "the aggregate and the errored run are left out";
  EXPECT_EQ(rows[0].name, "BM_TriTri/core");
  EXPECT_DOUBLE_EQ(rows[0].ns_per_iter, 35.0e3);
  EXPECT_DOUBLE_EQ(rows[0].ns_per_item, 40.0);
  EXPECT_TRUE(rows[0].counters.empty());
  EXPECT_EQ(rows[1].name, "BM_ClothStep/core-symplectic/16");
  EXPECT_EQ(rows[1].label, "avx512");
  EXPECT_DOUBLE_EQ(rows[1].ns_per_iter, 8.0e6);
  EXPECT_EQ(rows[1].counters.size(), 2u);
  EXPECT_DOUBLE_EQ(ns_per_spring(&rows[1]), 8000.0);
  EXPECT_TRUE(std::isnan(ns_per_spring(&rows[0])));
  EXPECT_TRUE(std::isnan(ns_per_spring(nullptr)));
  EXPECT_DOUBLE_EQ(ns_per_item(rows, "BM_TriTri/core"), 40.0);
  EXPECT_DOUBLE_EQ(ns_per_item(rows, "BM_ClothStep/core-symplectic/16"), 8.0e6) << "no items: per iteration";
  EXPECT_TRUE(std::isnan(ns_per_item(rows, "BM_Nothing")));
  EXPECT_EQ(find_row(rows, "BM_Broken"), nullptr);
  EXPECT_TRUE(parse_benchmark_json(io::Json::parse("{}")).empty());
}

TEST(BenchmarkJson, ARepeatedBenchmarkIsItsMedian) {
  // --benchmark_repetitions=3 with and without --benchmark_report_aggregates_only: the median
  // stands for the benchmark, its runs, mean and spread are left out.
  const auto rows = parse_benchmark_json(io::Json::parse(R"({"benchmarks":[
    {"name":"BM_A/real_time","run_name":"BM_A/real_time","run_type":"iteration","real_time":5,"cpu_time":5,"time_unit":"ms"},
    {"name":"BM_A/real_time","run_name":"BM_A/real_time","run_type":"iteration","real_time":9,"cpu_time":9,"time_unit":"ms"},
    {"name":"BM_A/real_time_mean","run_name":"BM_A/real_time","run_type":"aggregate","aggregate_name":"mean",
     "real_time":7,"cpu_time":7,"time_unit":"ms"},
    {"name":"BM_A/real_time_median","run_name":"BM_A/real_time","run_type":"aggregate","aggregate_name":"median",
     "real_time":6,"cpu_time":5.5,"time_unit":"ms","pairs":88},
    {"name":"BM_A/real_time_stddev","run_name":"BM_A/real_time","run_type":"aggregate","aggregate_name":"stddev",
     "real_time":2,"cpu_time":2,"time_unit":"ms"},
    {"name":"BM_B","run_name":"BM_B","run_type":"iteration","real_time":3,"cpu_time":3,"time_unit":"ns"}
  ]})"));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].name, "BM_A/real_time");
  EXPECT_DOUBLE_EQ(rows[0].real_ns_per_iter, 6e6);
  EXPECT_DOUBLE_EQ(rows[0].ns_per_iter, 5.5e6);
  EXPECT_EQ(rows[0].counters["pairs"], 88);
  EXPECT_EQ(find_row(rows, "BM_A"), &rows[0]);
  EXPECT_EQ(rows[1].name, "BM_B") << "a benchmark without repetitions keeps its one row";
}

TEST(BenchmarkJson, RowsFoundByNameLessTheirMeasurementAttributes) {
  EXPECT_EQ(benchmark_base_name("BM_SelfCollisionLongRun/experiment/discrete/iterations:1"), "BM_SelfCollisionLongRun/experiment/discrete");
  EXPECT_EQ(benchmark_base_name("BM_ContinuousSelfCollision/threads:2/256/real_time"), "BM_ContinuousSelfCollision/threads:2/256");
  EXPECT_EQ(benchmark_base_name("BM_X/8/min_time:0.500/repeats:3/real_time"), "BM_X/8");
  EXPECT_EQ(benchmark_base_name("BM_ContinuousSelfCollision/threads:2/256"), "BM_ContinuousSelfCollision/threads:2/256")
      << "a benchmark's own arguments stay";
  BenchRow r;
  r.name = "BM_ContinuousSelfCollision/threads:2/256/real_time";
  const std::vector<BenchRow> rows = {r};
  EXPECT_EQ(find_row(rows, "BM_ContinuousSelfCollision/threads:2/256"), &rows[0]);
  EXPECT_EQ(find_row(rows, "BM_ContinuousSelfCollision/threads:2/256/real_time"), &rows[0]);
  EXPECT_EQ(find_row(rows, "BM_ContinuousSelfCollision/threads:2"), nullptr);
}

}  // namespace
}  // namespace tecido::suites::bench
