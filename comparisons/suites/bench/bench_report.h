#pragma once
/// The `bench` suite's report: the method (both commands, the machine), the figures docs/benchmarks.md
/// quotes, the project's speed goals against this run, every benchmark row and a scaling plot.
/// Every number is from this run; "met" and "not met" are computed from it.
#include "comparisons/suites/bench/figures.h"
#include "comparisons/suites/bench/goal_rows.h"
#include "comparisons/suites/bench/process_cost.h"
#include "comparisons/suites/suite.h"

#include <string>
#include <vector>

namespace tecido::suites::bench {

/// Min time, the machine (Google Benchmark's context), the two commands that produced the rows.
std::string method_markdown(const Settings& s, const io::Json& context, const std::string& command,
                            const std::string& sse2_command);

/// How the `selfcollide` processes were timed (mesh, rounds, the commands), or why they were not.
std::string process_markdown(const Settings& s, const ProcessRun& run);

/// The figures, each with the benchmark rows it is computed from.
std::string figures_markdown(const Figures& f, const Settings& s);

/// One row per goal (measured, target, met or not, the rows it is from), then how many were met and
/// which were not.
std::string goals_markdown(const std::vector<GoalRow>& goals);

/// Every row of the main run, then the SSE2-only run's, then the timed processes' (median CPU time).
std::string all_rows_markdown(const std::vector<BenchRow>& rows, const std::vector<BenchRow>& sse2_rows,
                              const std::vector<BenchRow>& process_rows);

/// Cost against n for the self-collision and cloth-step series under ctx.out_dir/bench; returns the
/// Markdown image link ("" without gnuplot) and adds the plot to `plots`.
std::string scaling_plot(const SuiteContext& ctx, const std::vector<BenchRow>& rows, std::vector<std::string>& plots);

/// report.json's data: {"benchmarks": [...], "sse2_benchmarks": [...], "process_timings": [...] (the timed
/// `selfcollide` processes, process_cost.h), "figures": {...}, "goals": goal_rows.h's goals_json}. A
/// row: {"name", "label", "ns_per_iteration" (CPU), "wall_ns_per_iteration", "ns_per_item", "counters"}.
io::Json bench_json(const Figures& f, const std::vector<BenchRow>& rows, const std::vector<BenchRow>& sse2_rows,
                    const std::vector<BenchRow>& process_rows, const std::vector<GoalRow>& goals);

}  // namespace tecido::suites::bench
