#pragma once
/// The `tradeoff` suite's report: the method, one table and cost/error plot per cloth size and the
/// Pareto fronts, each a short function of the values measured in the same run (what the tables
/// show is in findings.h); no measured number is a literal here.
#include "comparisons/suites/suite.h"
#include "comparisons/suites/tradeoff/engines.h"
#include "comparisons/suites/tradeoff/settings.h"
#include "comparisons/suites/tradeoff/size_analysis.h"

#include <string>
#include <vector>

namespace tecido::suites::tradeoff {

/// The scene and the method, from the settings.
std::string method_markdown(const Settings& s);
/// One size's heading, reference and conditioning line, and table of every point.
std::string size_markdown(const SizeAnalysis& a, const std::vector<TradeoffEngine>& engines);
/// The size's cost/error data file (one block per engine's counted points, then the front) under
/// ctx.out_dir/tradeoff, and its plot with gnuplot; returns the Markdown image link or "".
std::string size_plot(const SuiteContext& ctx, const SizeAnalysis& a, const std::vector<TradeoffEngine>& engines,
                      std::vector<std::string>& plots);
/// The gnuplot data file of a size: the counted points of each engine in `plotted` order (h, cost,
/// error per line, blocks separated by two blank lines), then the front's.
std::string dat_text(const SizeAnalysis& a, const std::vector<TradeoffEngine>& engines, std::vector<std::size_t>& plotted);
/// The gnuplot script plotting dat_text's blocks (cost against error, log-log) into <tag>.svg.
std::string gnuplot_script(const std::string& tag, int n, const std::vector<std::string>& names);
/// Every size's front in one table.
std::string fronts_markdown(const std::vector<SizeAnalysis>& sizes, const std::vector<TradeoffEngine>& engines);
/// The machine-readable results of a size.
io::Json size_json(const SizeAnalysis& a, const std::vector<TradeoffEngine>& engines);

}  // namespace tecido::suites::tradeoff
