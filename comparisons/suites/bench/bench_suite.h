#pragma once
/// Suite `bench`: runs build/bin/tecido-bench (Google Benchmark), then its cloth step again with
/// TECIDO_SIMD=sse2, then times the whole `tecido selfcollide` process on a real-sized folding
/// cloth, and reports time per pair, frame, step and spring, ratios against the reference engines
/// measured in the same run, every speed goal of the project (issue 24's included) met or not, and
/// a scaling plot. Speed is reported, never checked: the suite declares no check (timings on a
/// shared machine are not a test).
///
/// Layout: settings.h (min time, sizes, goals), bench_runner.* (running tecido-bench),
/// benchmark_json.* (its output), process_cost.* and folding_cloth.* (the timed `selfcollide`
/// processes and their mesh), figures.* (the figures docs/benchmarks.md quotes), goal_rows.* (the
/// goals against the rows), bench_report.* (tables, prose, plot, report.json's data); this file
/// runs and assembles.
#include "comparisons/suites/suite.h"

namespace tecido::suites {

SuiteResult run_bench_suite(const SuiteContext& ctx);

}  // namespace tecido::suites
