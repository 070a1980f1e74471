#pragma once
/// Suite `bench`: runs build/bin/tecido-bench (Google Benchmark) and turns its JSON into tables
/// of time per item and ratios against the reference engines measured in the same run, plus a
/// log-log cost-versus-n scaling plot. Speed is reported, never checked: this suite has no
/// pass/fail checks (timings on a shared machine are not a test).
#include "comparisons/suites/suite.h"

namespace tecido::suites {

struct BenchRow {
  std::string name;          ///< e.g. "BM_TriTri/core", "BM_ClothStep/core-symplectic/64"
  double ns_per_iter = 0.0;  ///< real time per iteration [ns]
  double ns_per_item = 0.0;  ///< 1e9 / items_per_second when the benchmark counts items, else 0
  io::Json counters = io::Json::object();
};

/// Parses Google Benchmark's JSON output (aggregates ignored).
std::vector<BenchRow> parse_benchmark_json(const io::Json& doc);

SuiteResult run_bench_suite(const SuiteContext& ctx);

}  // namespace tecido::suites
