#pragma once
/// Suite `bench`: runs build/bin/tecido-bench (Google Benchmark), then its cloth step again with
/// TECIDO_SIMD=sse2, and reports time per pair, frame, step and spring, ratios against the
/// reference engines measured in the same run, the project's speed goals against them and a
/// scaling plot. Speed is reported, never checked: the suite declares no check (timings on a
/// shared machine are not a test).
///
/// Layout: settings.h (min time, sizes, goals), bench_runner.* (running tecido-bench),
/// benchmark_json.* (its output), figures.* (the figures docs/benchmarks.md quotes), bench_report.*
/// (tables, prose, plot); this file runs and assembles.
#include "comparisons/suites/suite.h"

namespace tecido::suites {

SuiteResult run_bench_suite(const SuiteContext& ctx);

}  // namespace tecido::suites
