#include "comparisons/suites/bench/bench_suite.h"

#include "comparisons/suites/bench/bench_report.h"
#include "comparisons/suites/bench/bench_runner.h"
#include "comparisons/suites/bench/process_cost.h"

namespace tecido::suites {

SuiteResult run_bench_suite(const SuiteContext& ctx) {
  SuiteResult res;
  res.name = "bench";
  const bench::Settings s = bench::settings(ctx.quick);
  const std::string bin = bench::bench_binary();
  if (bin.empty()) {
    res.markdown = "`tecido-bench` was not found next to `tecido` (built with TECIDO_BENCH=OFF?): no timings.\n";
    return res;
  }
  const std::string dir = ctx.out_dir + "/bench";
  const bench::BenchRun main = bench::run_bench(bin, dir, "bench", s.min_time, s.main_filter, "", s.repetitions);
  if (!main.error.empty()) {
    res.markdown = main.error + ".\n";
    return res;
  }
  const bench::BenchRun sse2 = bench::run_bench(bin, dir, "bench-sse2", s.min_time, s.sse2_filter, "sse2");
  const bench::ProcessRun process =
      bench::time_selfcollide(bench::own_binary(), dir, s.process_n, s.process_rounds, s.process_threads);
  const auto rows = bench::parse_benchmark_json(main.doc);
  const auto sse2_rows = sse2.error.empty() ? bench::parse_benchmark_json(sse2.doc) : std::vector<bench::BenchRow>{};
  const bench::Figures f = bench::derive_figures(rows, sse2_rows, s);
  std::vector<bench::BenchRow> all = rows;
  all.insert(all.end(), process.rows.begin(), process.rows.end());
  const auto goals = bench::goal_rows(all, s, bench::Goals{});
  res.markdown = bench::method_markdown(s, main.doc.value("context", io::Json()), main.command, sse2.command) +
                 (sse2.error.empty() ? "" : sse2.error + " (this CPU may lack SSE2).\n\n") +
                 bench::process_markdown(s, process) + bench::figures_markdown(f, s) + bench::goals_markdown(goals) +
                 bench::all_rows_markdown(rows, sse2_rows, process.rows) + bench::scaling_plot(ctx, rows, res.plots);
  res.data = bench::bench_json(f, rows, sse2_rows, process.rows, goals);
  return res;
}

}  // namespace tecido::suites
