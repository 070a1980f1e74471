#include "comparisons/suites/report.h"

#include "comparisons/engines/outside/outside_engines.h"
#include "comparisons/io/atomic_file.h"
#include "comparisons/io/provenance.h"
#include "comparisons/suites/report_html.h"
#include "comparisons/view/viewer_assets.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace tecido::suites {

double check_margin(const Check& c) {
  if (!std::isfinite(c.value)) return -std::numeric_limits<double>::infinity();
  const double m = std::min(c.value - c.lo, c.hi - c.value);
  const double w = c.hi - c.lo;
  return (std::isfinite(w) && w > 0.0) ? m / w : m;
}

io::Json report_json(const std::vector<SuiteResult>& results, const SuiteContext& ctx) {
  io::Json suites = io::Json::array();
  for (const auto& r : results) {
    io::Json checks = io::Json::array();
    for (const auto& c : r.checks) {
      io::Json j{{"name", c.name},
                 {"value", std::isfinite(c.value) ? io::Json(c.value) : io::Json(nullptr)},
                 {"expected", {c.lo, c.hi}},
                 {"pass", c.pass}};
      if (!c.note.empty()) j["note"] = c.note;
      if (!c.reason.empty()) j["reason"] = c.reason;
      if (!c.tolerance.empty()) j["tolerance"] = c.tolerance;
      checks.push_back(std::move(j));
    }
    suites.push_back({{"name", r.name}, {"checks", checks}, {"data", r.data}, {"plots", r.plots}, {"seconds", r.seconds}});
  }
  io::Json j{{"seed", ctx.seed},
             {"quick", ctx.quick},
             {"tolerances", ctx.tolerances ? ctx.tolerances->file() : ""},
             {"suites", suites},
             {"tecido", io::provenance_json()}};
  if (ctx.outside && !ctx.outside->empty()) j["outside_engines"] = outside::doors_json(*ctx.outside);
  return j;
}

std::string report_markdown(const std::vector<SuiteResult>& results, const SuiteContext& ctx) {
  std::string md = "# tecido report\n\n" + io::provenance_markdown() + "\n\n";
  int passed = 0, failed = 0;
  for (const auto& r : results)
    for (const auto& c : r.checks) (c.pass ? passed : failed)++;
  md += fmt::format("**{}** — {} checks passed, {} failed. Seed {}{}.\n\n", failed == 0 ? "PASS" : "FAIL", passed,
                    failed, ctx.seed, ctx.quick ? ", quick mode (smaller counts, same checks)" : "");
  md += "| suite | passed | failed | worst check | value | expected | margin | time [s] |\n";
  md += "|---|---:|---:|---|---:|---|---:|---:|\n";
  for (const auto& r : results) {
    int p = 0, f = 0;
    const Check* worst = nullptr;
    for (const auto& c : r.checks) {
      (c.pass ? p : f)++;
      if (!worst || check_margin(c) < check_margin(*worst)) worst = &c;
    }
    if (worst) {
      md += fmt::format("| {} | {} | {} | `{}` | {:.4g} | [{:.4g}, {:.4g}] | {:+.3f} | {:.1f} |\n", r.name, p, f,
                        worst->name, worst->value, worst->lo, worst->hi, check_margin(*worst), r.seconds);
    } else {
      md += fmt::format("| {} | 0 | 0 | (no checks) | | | | {:.1f} |\n", r.name, r.seconds);
    }
  }
  md += "\nMargin: distance of the value to the nearer end of its band, as a fraction of the band's width "
        "(negative = outside). Tolerances: `" +
        (ctx.tolerances ? ctx.tolerances->file() : std::string("?")) + "`.";
  if (!ctx.gnuplot) md += " gnuplot was not found, so this report has tables but no plots.";
  md += "\n\n";
  if (ctx.outside) md += outside::doors_markdown(*ctx.outside);
  for (const auto& r : results) {
    md += "## " + r.name + "\n\n" + r.markdown + "\n";
    std::vector<const Check*> failing;
    for (const auto& c : r.checks)
      if (!c.pass) failing.push_back(&c);
    if (!failing.empty()) {
      md += "Failed checks:\n\n| check | value | expected | reason |\n|---|---:|---|---|\n";
      for (const Check* c : failing)
        md += fmt::format("| `{}` | {:.6g} | [{:.6g}, {:.6g}] | {} |\n", c->name, c->value, c->lo, c->hi,
                          c->reason.empty() ? "outside the band" : c->reason);
      md += "\n";
    }
  }
  return md;
}

int write_report(const std::vector<SuiteResult>& results, const SuiteContext& ctx) {
  io::write_file_atomic(ctx.out_dir + "/report.json", report_json(results, ctx).dump(2) + "\n");
  io::write_file_atomic(ctx.out_dir + "/report.md", report_markdown(results, ctx));
  view::copy_viewer_assets(ctx.out_dir);  // tecido.css for report.html, the viewer for the views
  io::write_file_atomic(ctx.out_dir + "/report.html", report_html(results, ctx));
  int failed = 0;
  for (const auto& r : results)
    for (const auto& c : r.checks) failed += c.pass ? 0 : 1;
  return failed;
}

}  // namespace tecido::suites
