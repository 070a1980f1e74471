#include "comparisons/suites/order/order_report.h"

#include "comparisons/io/atomic_file.h"
#include "comparisons/io/gnuplot.h"
#include "comparisons/suites/sweep.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tecido::suites::order {

std::string method_markdown(const Settings& s, double band) {
  return fmt::format(
      "Global position error at T against the analytic solution, for h = {} s halved {} times. The observed order "
      "of each halving is log2(e(h)/e(h/2)); the fitted order is the least-squares slope of log e against log h over "
      "the asymptotic range, found as the longest run of at least {} halvings whose observed orders agree (within {} "
      "from one halving to the next) with errors between the round-off floor ({:g} x scale) and the "
      "instability/pre-asymptotic limit ({:g} x scale). Checks: fitted order within ±{} of the order each engine "
      "claims (euler 1, symplectic 1, midpoint 2, rk4 4). A run that blows up has an infinite error and is left out "
      "of the fit; an engine with no asymptotic range fails its check with that reason.\n\n",
      s.h0, s.halvings, s.min_halvings, s.agree, s.roundoff_floor, s.too_big, band);
}

namespace {
/// "2" or "–" (claims no order).
std::string claims(double order) { return order > 0.0 ? fmt::format("{:g}", order) : "–"; }
}  // namespace

std::string outside_markdown(const std::vector<OrderEngine>& engines) {
  std::string list;
  for (const OrderEngine& e : engines)
    if (e.outside)
      list += (list.empty() ? "" : "; ") + e.name +
              (e.claimed_order > 0.0 ? fmt::format(" claims order {:g}, checked in the same band", e.claimed_order)
                                     : std::string(" claims no order: its fit is reported, not checked"));
  if (list.empty()) return "";
  return "Outside engines (doors in the report's \"Outside engines\" table): " + list +
         ". Each run of an outside engine takes its T/h steps in one call of its door (one round trip for a "
         "process), and its wall times below include that call. A scene an engine refuses fails its check with "
         "\"not modelled by\" and its reason.\n\n";
}

std::string fit_table(const Problem& p, const std::vector<EngineRuns>& runs) {
  std::string md = fmt::format("### {}\n\n{}; T = {} s.\n\n", p.name, p.about, p.T);
  md += "| engine | claims | fitted order | range h | observed orders per halving | round-off below h | excluded above h |\n"
        "|---|---:|---:|---|---|---:|---:|\n";
  for (const EngineRuns& r : runs) {
    if (!r.error.empty()) {
      md += fmt::format("| {} | {} | – | – | failed: {} | – | – |\n", r.engine, claims(r.claimed_order), r.error);
      continue;
    }
    std::string obs;
    for (double o : r.fit.observed) obs += std::isfinite(o) ? fmt::format("{:.2f} ", o) : "– ";
    const std::string range =
        r.fit.first >= 0 ? fmt::format("{:.3g} … {:.3g}", r.samples[r.fit.first].h, r.samples[r.fit.last].h) : "none";
    md += fmt::format("| {} | {} | {:.3f} | {} | {}| {} | {} |\n", r.engine, claims(r.claimed_order), r.fit.slope, range, obs,
                      r.fit.roundoff_below_h > 0 ? fmt::format("{:.3g}", r.fit.roundoff_below_h) : "–",
                      r.fit.unstable_above_h > 0 ? fmt::format("{:.3g}", r.fit.unstable_above_h) : "–");
  }
  return md;
}

std::string fit_plot(const SuiteContext& ctx, const Problem& p, const std::vector<EngineRuns>& runs,
                     std::vector<std::string>& plots) {
  std::string dat, plot_h = "plot ", plot_t = "plot ";
  int block = 0;
  for (const EngineRuns& r : runs) {
    if (!r.error.empty()) continue;
    dat += fmt::format("# {}\n", r.engine);
    for (const Sample& s : r.samples)
      if (std::isfinite(s.error) && s.error > 0) dat += fmt::format("{:.17g} {:.17g} {:.17g}\n", s.h, s.error, s.seconds);
    dat += "\n\n";  // gnuplot blocks are separated by two blank lines
    plot_h += fmt::format("{}'{}.dat' index {} using 1:2 with linespoints title '{}'", block ? ", " : "", p.name, block, r.engine);
    plot_t += fmt::format("{}'{}.dat' index {} using 3:2 with linespoints title '{}'", block ? ", " : "", p.name, block, r.engine);
    ++block;
  }
  const std::string dir = ctx.out_dir + "/order";
  io::write_file_atomic(dir + "/" + p.name + ".dat", dat);
  if (!ctx.gnuplot || block == 0) return "";
  const std::string script = fmt::format(
      "set terminal svg size 900,380 dynamic font 'sans,11'\nset output '{0}.svg'\nset multiplot layout 1,2 title '{0}'\n"
      "set logscale xy\nset format xy '10^{{%L}}'\nset key bottom right\nset grid\n"
      "set xlabel 'step h [s]'\nset ylabel 'error at T [m]'\n{1}\nset xlabel 'wall time [s]'\n{2}\nunset multiplot\n",
      p.name, plot_h, plot_t);
  if (!io::run_gnuplot(dir, p.name, script)) return "";
  plots.push_back("order/" + p.name + ".svg");
  return fmt::format("\n![{0}: error vs h and error vs wall time](order/{0}.svg)\n", p.name);
}

namespace {
/// "on 3 of 4 problems (by 12.7x to 767x)" for the ratios > 1 among `ratios` (NaN: missing).
std::string wins(const std::vector<double>& ratios) {
  int n = 0, won = 0;
  double lo = INFINITY, hi = 0.0;
  for (double r : ratios) {
    if (!std::isfinite(r)) continue;
    ++n;
    if (r > 1.0) {
      ++won;
      lo = std::min(lo, r);
      hi = std::max(hi, r);
    }
  }
  if (won == 0) return fmt::format("on none of the {} problems with both runs", n);
  return fmt::format("on {} of {} problems (error smaller by {:.3g}x to {:.3g}x)", won, n, lo, hi);
}
}  // namespace

std::string head_to_head_markdown(const Settings& s, const std::vector<HeadToHead>& rows) {
  const double h = s.h0 / std::pow(2.0, s.head_to_head);
  std::string md = fmt::format(
      "### Euler versus midpoint (the seed's question)\n\nAt equal step h = {:g} s, and at equal cost (midpoint "
      "pays two force evaluations a step, so it gets 2h for Euler's h):\n\n"
      "| problem | e_euler(h) | e_midpoint(h) | ratio at equal h | e_midpoint(2h) | ratio at equal cost |\n"
      "|---|---:|---:|---:|---:|---:|\n",
      h);
  std::vector<double> equal_h, equal_cost;
  for (const HeadToHead& r : rows) {
    equal_h.push_back(r.euler / r.midpoint);
    equal_cost.push_back(r.euler / r.midpoint_2h);
    md += fmt::format("| {} | {:.3e} | {:.3e} | {:.3g} | {:.3e} | {:.3g} |\n", r.problem, r.euler, r.midpoint,
                      equal_h.back(), r.midpoint_2h, equal_cost.back());
  }
  md += fmt::format("\nFrom this table: at equal step midpoint is more accurate {}; at equal cost it is more accurate {}.\n",
                    wins(equal_h), wins(equal_cost));
  return md;
}

io::Json runs_json(const EngineRuns& r) {
  io::Json js = io::Json::array();
  for (const Sample& s : r.samples)
    js.push_back({{"h", s.h}, {"error", std::isfinite(s.error) ? io::Json(s.error) : io::Json(nullptr)}});
  const bool fitted = r.fit.first >= 0;
  return {{"samples", js},
          {"claimed_order", r.claimed_order > 0.0 ? io::Json(r.claimed_order) : io::Json(nullptr)},
          {"fitted_order", std::isfinite(r.fit.slope) ? io::Json(r.fit.slope) : io::Json(nullptr)},
          {"range", fitted ? io::Json({r.samples[r.fit.first].h, r.samples[r.fit.last].h}) : io::Json(nullptr)},
          {"error", r.error.empty() ? io::Json(nullptr) : io::Json(r.error)}};
}

}  // namespace tecido::suites::order
