#include "comparisons/suites/bench/bench_report.h"

#include "comparisons/io/atomic_file.h"
#include "comparisons/io/gnuplot.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <map>

namespace tecido::suites::bench {

namespace {
/// v with `digits` significant digits, but whole numbers in full from 10^digits on (no exponent).
std::string number(double v, int digits) {
  return std::fabs(v) >= std::pow(10.0, digits) ? fmt::format("{:.0f}", v) : fmt::format("{:.{}g}", v, digits);
}

/// "a-b" with 2 significant digits, one value when both ends agree, "–" when empty.
std::string span_text(const Span& s, const std::string& unit = "") {
  if (s.count == 0) return "–";
  const std::string lo = number(s.lo, 2), hi = number(s.hi, 2);
  return (lo == hi ? lo : lo + "-" + hi) + unit;
}

std::string value_text(double v, const std::string& unit = "") { return std::isfinite(v) ? number(v, 3) + unit : "–"; }

std::string sizes_text(const Settings& s) {
  return s.cloth_sizes.empty() ? "" : fmt::format("{0}x{0}..{1}x{1}", s.cloth_sizes.front(), s.cloth_sizes.back());
}
}  // namespace

std::string method_markdown(const Settings& s, const io::Json& context, const std::string& command,
                            const std::string& sse2_command) {
  std::string md = fmt::format(
      "Google Benchmark, CPU time of the benchmark's one thread (wall time for the threaded rows), min time {:g} s per benchmark{}, "
      "this machine, this run: `{}` (rows in `bench/bench.json`), then `{}` (`bench/bench-sse2.json`), the spring kernel of a CPU "
      "without AVX. Ratios compare engines measured in the same run. These are measurements, never checks.\n\n",
      s.min_time, s.repetitions > 1 ? fmt::format(", each the median of {} repetitions (the first run)", s.repetitions) : "", command,
      sse2_command);
  if (context.is_object())
    md += fmt::format("Machine: {} CPUs at {} MHz; Google Benchmark library build type {}.\n\n",
                      context.value("num_cpus", 0), context.value("mhz_per_cpu", 0), context.value("library_build_type", "?"));
  return md;
}

std::string process_markdown(const Settings& s, const ProcessRun& run) {
  std::string md = fmt::format(
      "The whole `tecido selfcollide` process on a {0} x {0} cloth folding onto itself ({1} triangles; "
      "comparisons/suites/bench/folding_cloth.h, the frames `bench/fold_{0}_t0.obj` and `bench/fold_{0}_t1.obj` of this "
      "run), timed as a child of this process: medians of {2} rounds, the commands in turn (order rotating), CPU time of "
      "the child (user + system, all threads) and wall time; rows `process/selfcollide/...`. Commands:",
      s.process_n, 2 * (s.process_n - 1) * (s.process_n - 1), s.process_rounds);
  for (const std::string& c : run.commands) md += " `" + c + "`;";
  md.back() = '.';
  if (!run.error.empty()) md += " " + run.error + ".";
  return md + "\n\n";
}

std::string figures_markdown(const Figures& f, const Settings& s) {
  std::string tt;
  for (const auto& [engine, ns] : f.tritri_ns) tt += fmt::format("{}{} {}", tt.empty() ? "" : ", ", engine, value_text(ns));
  std::string md = "### Figures\n\nThe benchmark figures of docs/benchmarks.md, from this run.\n\n| measurement | this run | from |\n|---|---|---|\n";
  md += fmt::format("| tri-tri, ns per random pair | {} | `BM_TriTri/<engine>` |\n", tt.empty() ? "–" : tt);
  md += fmt::format("| core tri-tri time / FCL's, / CGAL exact's | {}, {} | `BM_TriTri/core` over `/fcl`, `/exact` |\n",
                    value_text(f.tritri_core_vs_fcl), value_text(f.tritri_core_vs_exact));
  md += fmt::format("| self-collision of a folded 256x256 cloth frame, one thread: core (flat frame; FCL's BVH) | {} ({}; {}) | "
                    "`BM_SelfCollision/core/256` (`core-flat`, `fcl`) |\n",
                    value_text(f.selfcollision_ms, " ms"), value_text(f.selfcollision_flat_ms, " ms"),
                    value_text(f.selfcollision_fcl_ms, " ms"));
  const std::string n = sizes_text(s);
  md += fmt::format("| cloth step {}, core symplectic / Bullet classic (10 iterations) | {}x | `BM_ClothStep/core-symplectic/n` "
                    "over `bullet-classic/n` |\n", n, span_text(f.cloth_vs_bullet));
  md += fmt::format("| cloth step {}, core ns per spring (kernel {}) | {} | `BM_ClothStep/core-symplectic/n` per spring |\n", n,
                    f.kernel.empty() ? "?" : f.kernel, span_text(f.ns_per_spring, " ns"));
  md += fmt::format("| the same without AVX (kernel {}) | {} | the `TECIDO_SIMD=sse2` run |\n",
                    f.sse2_kernel.empty() ? "?" : f.sse2_kernel, span_text(f.sse2_ns_per_spring, " ns"));
  md += fmt::format("| cloth step {}, Bullet classic ns per link | {} | `BM_ClothStep/bullet-classic/n` per link |\n", n,
                    span_text(f.bullet_ns_per_link, " ns"));
  return md + "\n";
}

std::string goals_markdown(const std::vector<GoalRow>& goals) {
  std::string md = "### Goals\n\n| goal | measured | target | | from |\n|---|---:|---:|---|---|\n", missed;
  int met = 0, measured = 0;
  for (const GoalRow& r : goals) {
    const std::string unit = r.unit.empty() ? "" : " " + r.unit;
    md += fmt::format("| {} | {} | {} {:.3g}{} | {} | {} |\n", r.what, value_text(r.value, unit), r.at_least ? "≥" : "≤", r.target,
                      unit, r.measured() ? (r.met() ? "met" : "not met") : "not measured", r.from);
    measured += r.measured() ? 1 : 0;
    met += r.met() ? 1 : 0;
    if (r.measured() && !r.met()) missed += (missed.empty() ? "" : "; ") + r.what;
  }
  md += fmt::format("\nIn this run {} of the {} measured goals were met{}.\n\n", met, measured,
                    missed.empty() ? "" : "; not met: " + missed);
  return md;
}

std::string all_rows_markdown(const std::vector<BenchRow>& rows, const std::vector<BenchRow>& sse2_rows,
                              const std::vector<BenchRow>& process_rows) {
  std::string md = "### All benchmarks\n\n| benchmark | label | time per iteration | ns per item |\n|---|---|---:|---:|\n";
  auto add = [&md](const std::vector<BenchRow>& rs, const std::string& prefix) {
    for (const auto& r : rs)
      md += fmt::format("| {}`{}` | {} | {:.4g} µs | {} |\n", prefix, r.name, r.label, r.ns_per_iter / 1e3,
                        r.ns_per_item > 0 ? fmt::format("{:.1f}", r.ns_per_item) : "");
  };
  add(rows, "");
  add(sse2_rows, "`TECIDO_SIMD=sse2` ");
  add(process_rows, "");
  return md;
}

std::string scaling_plot(const SuiteContext& ctx, const std::vector<BenchRow>& rows, std::vector<std::string>& plots) {
  std::map<std::string, std::string> series;  // "BM_SelfCollision/core" -> "n ms\n..."
  for (const auto& r : rows) {
    const auto slash = r.name.rfind('/');
    if (slash == std::string::npos || (r.name.rfind("BM_SelfCollision/", 0) != 0 && r.name.rfind("BM_ClothStep/", 0) != 0)) continue;
    const std::string tail = r.name.substr(slash + 1);
    if (!tail.empty() && std::isdigit(static_cast<unsigned char>(tail[0])))
      series[r.name.substr(0, slash)] += fmt::format("{} {:.9g}\n", tail, r.ns_per_iter / 1e6);
  }
  if (!ctx.gnuplot || series.empty()) return "";
  std::string dat, plot = "plot ";
  int i = 0;
  for (const auto& [name, pts] : series) {
    dat += "# " + name + "\n" + pts + "\n\n";
    plot += fmt::format("{}'scaling.dat' index {} using 1:2 with linespoints title '{}'", i ? ", " : "", i, name.substr(3));
    ++i;
  }
  const std::string dir = ctx.out_dir + "/bench";
  io::write_file_atomic(dir + "/scaling.dat", dat);
  const std::string script = fmt::format(
      "set terminal svg size 800,420 dynamic font 'sans,11'\nset output 'scaling.svg'\nset title 'cost vs cloth size n (n x n nodes)'\n"
      "set logscale xy\nset grid\nset key outside right\nset xlabel 'n'\nset ylabel 'ms per frame / step'\n{}\n",
      plot);
  if (!io::run_gnuplot(dir, "scaling", script)) return "";
  plots.push_back("bench/scaling.svg");
  return "\n![scaling](bench/scaling.svg)\n";
}

namespace {
io::Json rows_json(const std::vector<BenchRow>& rows) {
  io::Json a = io::Json::array();
  for (const auto& r : rows)
    a.push_back({{"name", r.name}, {"label", r.label}, {"ns_per_iteration", r.ns_per_iter},
                 {"wall_ns_per_iteration", r.real_ns_per_iter}, {"ns_per_item", r.ns_per_item}, {"counters", r.counters}});
  return a;
}

io::Json num_or_null(double v) { return std::isfinite(v) ? io::Json(v) : io::Json(nullptr); }
io::Json span_json(const Span& s) { return {num_or_null(s.lo), num_or_null(s.hi)}; }
}  // namespace

io::Json bench_json(const Figures& f, const std::vector<BenchRow>& rows, const std::vector<BenchRow>& sse2_rows,
                    const std::vector<BenchRow>& process_rows, const std::vector<GoalRow>& goals) {
  io::Json tt = io::Json::object();
  for (const auto& [engine, ns] : f.tritri_ns) tt[engine] = num_or_null(ns);
  const io::Json figures = {{"ns_per_tritri_pair", tt},
                            {"tritri_core_over_fcl", num_or_null(f.tritri_core_vs_fcl)},
                            {"tritri_core_over_exact", num_or_null(f.tritri_core_vs_exact)},
                            {"ms_per_selfcollision_frame_256", {{"core", num_or_null(f.selfcollision_ms)},
                                                                {"core-flat", num_or_null(f.selfcollision_flat_ms)},
                                                                {"fcl", num_or_null(f.selfcollision_fcl_ms)}}},
                            {"cloth_step_core_over_bullet_classic", span_json(f.cloth_vs_bullet)},
                            {"ns_per_spring", {{"kernel", f.kernel}, {"range", span_json(f.ns_per_spring)}}},
                            {"ns_per_spring_sse2", {{"kernel", f.sse2_kernel}, {"range", span_json(f.sse2_ns_per_spring)}}},
                            {"ns_per_bullet_link", span_json(f.bullet_ns_per_link)}};
  return {{"benchmarks", rows_json(rows)}, {"sse2_benchmarks", rows_json(sse2_rows)}, {"process_timings", rows_json(process_rows)},
          {"figures", figures}, {"goals", goals_json(goals)}};
}

}  // namespace tecido::suites::bench
