#include "comparisons/suites/tradeoff/tradeoff_report.h"

#include "comparisons/io/atomic_file.h"
#include "comparisons/io/gnuplot.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <cmath>

namespace tecido::suites::tradeoff {

namespace {

std::string g3(double x) { return std::isfinite(x) ? fmt::format("{:.3g}", x) : "–"; }

io::Json or_null(double x) { return std::isfinite(x) ? io::Json(x) : io::Json(nullptr); }

}  // namespace

std::string method_markdown(const Settings& s) {
  std::string sizes;
  for (const Size& z : s.sizes) sizes += (sizes.empty() ? "" : ", ") + fmt::format("{}^2 ({} steps)", z.n, z.steps);
  return fmt::format(
      "The scene: a curtain, a 1 m x 1 m cloth of n x n nodes (the cloth builder's grid, type B springs 1 N/m, type A "
      "0.5 N/m, 0.1 kg, undamped) hanging in the vertical plane y = 0, released at rest from its rest shape with its "
      "two top corners (0, 0) and (0, n-1) pinned: under gravity it stretches and its top edge sags between the pins; "
      "no planes, {0:g} s simulated; sizes {1}. Gravity lies in the cloth's plane, so the motion stays in it, by "
      "design: out of the plane the sagging top edge is under compression and buckles, and the problem becomes so "
      "ill-conditioned that no reference could be called converged; the conditioning line under each size measures "
      "both (every free node nudged by {2:g} m at t = 0 in seeded directions, symplectic Euler at h_min, RMS change at "
      "t = {0:g} s per metre of nudge). The step sweep starts at h0 = 2^ceil(log2(2 / omega_bound)), omega_bound "
      "being the Gershgorin bound on the springs' highest frequency (so h0 sits near symplectic Euler's limit), and "
      "halves it. Cost = wall seconds per simulated second (each run on one thread, while other cases run on the other "
      "threads: `--threads 1` gives the quietest timings; runs under {3:g} s are repeated and the fastest kept; "
      "timings are this machine's, this run's, and are the one thing here that is not reproducible). Error = RMS over "
      "nodes of the distance at t = {0:g} s to the reference: core RK4 at h_ref = h_min / {4}. The reference's own "
      "error is estimated by step halving (RK4 at 2 h_ref against it: the difference / 15 for a 4th-order method; the "
      "observed order, from RK4 at h_min and h_min / 2 against the reference, is checked to be about 4 so that the "
      "estimate holds), the consistency test by which Erez, Tassa and Todorov (2015) compare engines. Every run goes "
      "through one guarded runner: it fails at a non-finite state or a node more than {5:g} m from its start. A run "
      "counts when it stays finite and its error is at most {6:g} m (a setting); others are listed as unstable. The "
      "Pareto front holds the counted runs that no other run beats in both cost and error; each front point is rerun "
      "and must return bit-identical positions.\n\n",
      s.seconds, sizes, s.nudge, s.timing_min_seconds, s.reference_divisor, s.stray_limit, s.max_error);
}

std::string size_markdown(const SizeAnalysis& a, const std::vector<TradeoffEngine>& engines) {
  const ReferenceEstimate& r = a.reference;
  std::string md = fmt::format("### {0} x {0} nodes ({1} springs)\n\nomega_bound = {2:.4g} 1/s, h0 = {3} = {4:.4g} s, "
                               "reference RK4 at h_ref = {5:.4g} s",
                               a.n, a.springs, a.omega, h_label(a.swept.front()), a.swept.front(), r.h_ref);
  if (!r.failure.empty()) md += " (failed: " + r.failure + ")";
  md += fmt::format("; reference's estimated error {} m (RK4 at 2 h_ref = {:.4g} s differs from it by {} m RMS; observed "
                    "RK4 order {}). Conditioning: a nudge of every free node at t = 0 moves the nodes at the end by {} "
                    "times as much (RMS) within the plane, {} times out of it.\n\n"
                    "| engine | h [s] | status | cost [s/s] | force evals / s | RMS error [m] | front |\n"
                    "|---|---:|---|---:|---:|---:|:-:|\n",
                    g3(r.error), 2.0 * r.h_ref, g3(r.difference), g3(r.order), g3(r.conditioning_in),
                    g3(r.conditioning_out));
  for (int i = 0; i < static_cast<int>(a.points.size()); ++i) {
    const Point& p = a.points[i];
    const bool on = std::find(a.front.begin(), a.front.end(), i) != a.front.end();
    md += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", engines[p.engine].name, h_label(p.h), p.status,
                      g3(p.cost), g3(p.evals), g3(p.error), on ? "●" : "");
  }
  return md;
}

std::string dat_text(const SizeAnalysis& a, const std::vector<TradeoffEngine>& engines, std::vector<std::size_t>& plotted) {
  std::string dat;
  for (std::size_t e = 0; e < engines.size(); ++e) {
    std::string block;
    for (const Point& p : a.points)
      if (p.engine == e && p.counted && p.error > 0.0) block += fmt::format("{:.17g} {:.17g} {:.17g}\n", p.h, p.cost, p.error);
    if (block.empty()) continue;
    dat += fmt::format("# {}\n{}\n\n", engines[e].name, block);
    plotted.push_back(e);
  }
  dat += "# front\n";
  for (int i : a.front)
    if (a.points[i].error > 0.0) dat += fmt::format("{:.17g} {:.17g} {:.17g}\n", a.points[i].h, a.points[i].cost, a.points[i].error);
  return dat;
}

std::string gnuplot_script(const std::string& tag, int n, const std::vector<std::string>& names) {
  std::string plot = "plot ";
  for (std::size_t b = 0; b < names.size(); ++b)
    plot += fmt::format("'{}.dat' index {} using 2:3 with points pt {} ps 1.2 title '{}', ", tag, b, 5 + 2 * static_cast<int>(b),
                        names[b]);
  plot += fmt::format("'{}.dat' index {} using 2:3 with linespoints lw 2 lc rgb 'black' pt 6 ps 2.2 title 'Pareto front'",
                      tag, names.size());
  return fmt::format(
      "set terminal svg size 760,480 dynamic font 'sans,11'\nset output '{0}.svg'\n"
      "set title '{1} x {1} cloth: cost against error'\nset logscale xy\nset format xy '10^{{%L}}'\n"
      "set grid\nset key outside right\nset xlabel 'cost [wall s per simulated s]'\n"
      "set ylabel 'RMS error at the end [m]'\n{2}\n",
      tag, n, plot);
}

std::string size_plot(const SuiteContext& ctx, const SizeAnalysis& a, const std::vector<TradeoffEngine>& engines,
                      std::vector<std::string>& plots) {
  const std::string tag = fmt::format("cloth{}", a.n), dir = ctx.out_dir + "/tradeoff";
  std::vector<std::size_t> plotted;
  io::write_file_atomic(dir + "/" + tag + ".dat", dat_text(a, engines, plotted));
  if (!ctx.gnuplot || plotted.empty()) return "";
  std::vector<std::string> names;
  for (std::size_t e : plotted) names.push_back(engines[e].name);
  if (!io::run_gnuplot(dir, tag, gnuplot_script(tag, a.n, names))) return "";
  plots.push_back("tradeoff/" + tag + ".svg");
  return fmt::format("\n![{0}: cost against error](tradeoff/{0}.svg)\n", tag);
}

std::string fronts_markdown(const std::vector<SizeAnalysis>& sizes, const std::vector<TradeoffEngine>& engines) {
  std::string md = "### Pareto fronts\n\n| nodes | engine | h [s] | cost [s/s] | force evals / s | RMS error [m] |\n"
                   "|---|---|---:|---:|---:|---:|\n";
  for (const SizeAnalysis& a : sizes) {
    for (int i : a.front) {
      const Point& p = a.points[i];
      md += fmt::format("| {}^2 | {} | {} | {} | {} | {} |\n", a.n, engines[p.engine].name, h_label(p.h), g3(p.cost),
                        g3(p.evals), g3(p.error));
    }
    if (a.front.empty()) md += fmt::format("| {}^2 | (empty: no run counted) | | | | |\n", a.n);
  }
  return md + "\n";
}

io::Json size_json(const SizeAnalysis& a, const std::vector<TradeoffEngine>& engines) {
  io::Json runs = io::Json::array(), front = io::Json::array();
  for (const Point& p : a.points)
    runs.push_back({{"engine", engines[p.engine].name}, {"h", p.h}, {"counted", p.counted}, {"status", p.status},
                    {"seconds", or_null(p.cost)}, {"evaluations_per_second", or_null(p.evals)}, {"error", or_null(p.error)}});
  for (int i : a.front) {
    const Point& p = a.points[i];
    // "seconds" (wall s per simulated s) is the timing; the front's membership follows it.
    front.push_back({{"engine", engines[p.engine].name}, {"h", p.h}, {"seconds", p.cost}, {"error", p.error}});
  }
  const ReferenceEstimate& r = a.reference;
  return {{"nodes", a.n * a.n},
          {"omega_bound", a.omega},
          {"h_ref", r.h_ref},
          {"reference_error", or_null(r.error)},
          {"reference_order", or_null(r.order)},
          {"conditioning_in_plane", or_null(r.conditioning_in)},
          {"conditioning_out_of_plane", or_null(r.conditioning_out)},
          {"runs", runs},
          {"front", front}};
}

}  // namespace tecido::suites::tradeoff
