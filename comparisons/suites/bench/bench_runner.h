#pragma once
/// Running tecido-bench (Google Benchmark) from the `bench` suite.
#include "comparisons/io/json_reader.h"

#include <string>

namespace tecido::suites::bench {

/// The running executable's path (/proc/self/exe; "" when unknown): `tecido` when the suite runs.
std::string own_binary();

/// build/bin/tecido-bench: the file next to the running executable ("" when there is none).
std::string bench_binary();

/// One run of tecido-bench: its JSON document, or why there is none.
struct BenchRun {
  io::Json doc;
  std::string error;   ///< "" when the run succeeded
  std::string command;  ///< the command line, as a user would type it (for the report)
};

/// Google Benchmark's JSON with its non-numbers made JSON: a value NaN, inf or -inf (the
/// coefficient of variation of a counter that is 0 in every repetition is 0 / 0) becomes null.
std::string without_nan(std::string text);

/// Runs `bin` with --benchmark_format=json --benchmark_min_time=`min_time`, --benchmark_filter=`filter`
/// when not empty and TECIDO_SIMD=`simd` when not empty, and with `repetitions` > 1 each benchmark
/// that many times, the document holding their aggregates only (--benchmark_repetitions,
/// --benchmark_report_aggregates_only); the JSON goes to `dir`/`name`.json and stderr to
/// `dir`/`name`.stderr.
BenchRun run_bench(const std::string& bin, const std::string& dir, const std::string& name, double min_time,
                   const std::string& filter = "", const std::string& simd = "", int repetitions = 1);

}  // namespace tecido::suites::bench
