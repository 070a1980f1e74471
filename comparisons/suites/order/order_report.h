#pragma once
/// The `order` suite's report: the method paragraph, one fit table and plot per problem, and the
/// seed's question (Euler versus midpoint at equal step and at equal cost) with the conclusion
/// computed from that table.
#include "comparisons/suites/order/convergence.h"
#include "comparisons/suites/order/order_fit.h"
#include "comparisons/suites/order/settings.h"
#include "comparisons/suites/suite.h"

#include <string>
#include <vector>

namespace tecido::suites::order {

/// One engine's runs on one problem, fitted; `error` is set when its case threw.
struct EngineRuns {
  std::string engine;
  double claimed_order = 0.0;
  std::vector<Sample> samples;
  OrderFit fit;
  std::string error;
};

/// The method paragraph: steps, fit rules and the band, all from the run's settings.
std::string method_markdown(const Settings& s, double band);
/// What the report says about the outside engines among `engines` ("" when none): their claims and
/// that their wall times include their door's calls.
std::string outside_markdown(const std::vector<OrderEngine>& engines);
/// The fit table of one problem (one row per engine).
std::string fit_table(const Problem& p, const std::vector<EngineRuns>& runs);
/// The error-vs-step and error-vs-time data file and plot of one problem under ctx.out_dir/order;
/// returns the Markdown image link ("" without gnuplot) and adds the plot to `plots`.
std::string fit_plot(const SuiteContext& ctx, const Problem& p, const std::vector<EngineRuns>& runs,
                     std::vector<std::string>& plots);

/// Euler against midpoint on one problem at h = h0/2^j (equal step) and midpoint at twice that step
/// (equal cost: two force evaluations a step); NaN where a run is missing.
struct HeadToHead {
  std::string problem;
  double euler = NAN, midpoint = NAN, midpoint_2h = NAN;
};
/// The table and a conclusion derived from it (on how many problems midpoint wins at equal step
/// and at equal cost, and by what factors).
std::string head_to_head_markdown(const Settings& s, const std::vector<HeadToHead>& rows);

/// The machine-readable results of one engine on one problem.
io::Json runs_json(const EngineRuns& r);

}  // namespace tecido::suites::order
