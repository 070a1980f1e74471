#pragma once
/// Google Benchmark's JSON output (`--benchmark_format=json`), read into rows.
#include "comparisons/io/json_reader.h"

#include <string>
#include <vector>

namespace tecido::suites::bench {

struct BenchRow {
  std::string name;          ///< e.g. "BM_TriTri/core", "BM_ClothStep/core-symplectic/64"
  std::string label;         ///< the benchmark's label (core's cloth steps: the spring kernel in use)
  double ns_per_iter = 0.0;  ///< CPU time per iteration [ns]
  double real_ns_per_iter = 0.0;  ///< wall time per iteration [ns] (the threaded rows' measure)
  double ns_per_item = 0.0;  ///< 1e9 / items_per_second (a CPU-time rate) when the benchmark counts items, else 0
  io::Json counters = io::Json::object();  ///< user counters ("springs", "nodes", ...)
};

/// The rows of a document, in its order: a benchmark's median over its repetitions when the
/// document has one (named as its runs are), else its iteration row; other aggregates (mean,
/// stddev, ...) and errored runs left out.
std::vector<BenchRow> parse_benchmark_json(const io::Json& doc);

/// `name` less the measurement attributes Google Benchmark appends ("/real_time", "/iterations:1",
/// "/min_time:...", "/repeats:...", "/process_time", "/manual_time"):
/// "BM_SelfCollisionLongRun/experiment/discrete/iterations:1" -> "BM_SelfCollisionLongRun/experiment/discrete".
std::string benchmark_base_name(const std::string& name);

/// The row named `name`, or whose name less its attributes (benchmark_base_name) is `name`; nullptr when none.
const BenchRow* find_row(const std::vector<BenchRow>& rows, const std::string& name);

/// Nanoseconds per item of the row named `name` (per iteration when it counts no items); NaN when absent.
double ns_per_item(const std::vector<BenchRow>& rows, const std::string& name);

/// Nanoseconds per spring of a row with a "springs" counter; NaN when absent or without it.
double ns_per_spring(const BenchRow* row);

}  // namespace tecido::suites::bench
