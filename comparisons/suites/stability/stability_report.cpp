#include "comparisons/suites/stability/stability_report.h"

#include "comparisons/suites/stability/theory.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tecido::suites::stability {

namespace {

/// "0.01, 0.1, 1"
std::string list(const std::vector<double>& xs) {
  std::string out;
  for (double x : xs) out += fmt::format("{}{:g}", out.empty() ? "" : ", ", x);
  return out;
}

/// The bound the theory paragraph uses to show how the amplitude bound moves symplectic Euler's limit.
constexpr double kIllustrativeBound = 10.0;

}  // namespace

std::string settings_markdown(const Settings& s) {
  const OffsetSettings& o = s.offset;
  return fmt::format(
      "Settings of this run (`comparisons/suites/stability/settings.h`; the tolerance file holds only bands):\n\n"
      "- stable at h: {:g} periods within {:g}x the initial amplitude; bisection to {:g} of h (at most {} doublings, "
      "{} halvings from h = 1/omega)\n"
      "- grid: ks = {} N/m x m = {} kg\n"
      "- growth: c = {} over {:g} periods; horizons: {} periods, bisected to {:g}\n"
      "- offsets {} m: springs (ks = {:g} N/m, m = {:g} kg) for {:g} periods at dt = {:g} s, a drop for {} steps\n"
      "- mass ratio {:g} kg : {:g} kg on ks = {:g} N/m; near-zero rest lengths {} m; resting {} steps of {:g} s; "
      "tunnelling at {} m/s with dt = {} s over {:g} s\n\n",
      s.periods, s.amplitude_bound, s.rel_tol, s.max_doublings, s.max_halvings, list(s.stiffnesses), list(s.masses),
      list(s.growth_cs), s.growth_periods, list(s.horizons), s.horizon_rel_tol, list(o.offsets), o.stiffness, o.mass,
      o.periods, o.dt, o.drop_steps, s.mass_ratio.heavy, s.mass_ratio.light, s.mass_ratio.stiffness,
      list(s.near_zero.rest_lengths), s.resting.steps, s.resting.dt, list(s.tunnelling.speeds), list(s.tunnelling.dts),
      s.tunnelling.duration);
}

std::string method_markdown(const Settings& s) {
  const double B = s.amplitude_bound;
  std::string md = fmt::format(
      "The oscillator: a particle of mass m on a zero-rest-length spring of stiffness ks to a pinned particle "
      "(force -ks x, exactly linear in every direction), released at rest 1 m from the anchor; omega = sqrt(ks/m). "
      "**Stable at h** means: over {0:g} periods (2 pi/omega each) at step h the run stays finite and |x| never "
      "exceeds {1:g} times its initial value. The largest stable h is found by a deterministic bisection on h: "
      "start at h = 1/omega, double (or halve) to bracket, then bisect at the midpoint until the bracket is "
      "{2:g} of h wide. Grid: ks in {3:g}..{4:g} N/m ({5} values) x m in {6:g}..{7:g} kg ({8} values).\n\n",
      s.periods, B, s.rel_tol, s.stiffnesses.front(), s.stiffnesses.back(), s.stiffnesses.size(), s.masses.front(),
      s.masses.back(), s.masses.size());
  md += fmt::format(
      "Theory (linear stability of x'' = -omega^2 x, c = h omega): symplectic Euler's update has trace 2 - c^2 and "
      "determinant 1, so it is stable for c < {0:g}; RK4's amplification |R(ic)|^2 = 1 - c^6/72 + c^8/576 is <= 1 "
      "for c <= 2 sqrt 2 = {1:.3f}. Explicit Euler (|R|^2 = 1 + c^2) and midpoint (|R|^2 = 1 + c^4/4) amplify "
      "every oscillation at **every** h > 0: they have no stable step on an undamped oscillator, so the suite "
      "reports their measured growth per period instead. Near c = 2 symplectic Euler's invariant ellipse "
      "stretches: |x| peaks at 2/sqrt(4 - c^2) times the initial amplitude, so a bound of {2:g}x puts the "
      "measured limit at 2 sqrt(1 - 1/{2:g}^2) = {3:.7f} (a bound of {4:g}x would have stopped it at {5:.3f}).\n\n",
      stable_limit(IntegratorKind::Symplectic), stable_limit(IntegratorKind::RK4), B, bound_stretch_limit(B),
      kIllustrativeBound, bound_stretch_limit(kIllustrativeBound));
  return md;
}

std::string grid_heading(const Settings& s) {
  std::string limits;
  for (IntegratorKind k : s.bounded)
    limits += fmt::format("{}{} {:.4g}", limits.empty() ? "" : ", ", integrator_name(k), stable_limit(k));
  return fmt::format("### Largest stable step, h_max omega (theory: {})\n\n", limits);
}

namespace {
/// For symplectic Euler: how far the cells lie from 2 sqrt(1 - 1/B^2), against the bisection's bracket.
std::string bound_limited_summary(const Settings& s, const GridTable& t) {
  if (t.kind != IntegratorKind::Symplectic || !t.h_omega.complete()) return "";
  const double pred = bound_stretch_limit(s.amplitude_bound);
  const double dev = std::max(std::abs(t.h_omega.lo() - pred), std::abs(t.h_omega.hi() - pred)) / pred;
  return fmt::format(
      " Under the amplitude bound the theory's limit is 2 sqrt(1 - 1/{:g}^2) = {:.7f}; every cell lies within "
      "{:.2g} of it, {} the bisection's bracket ({:g}).",
      s.amplitude_bound, pred, dev, dev <= s.rel_tol ? "inside" : "outside", s.rel_tol);
}
}  // namespace

std::string grid_markdown(const Settings& s, const GridTable& t) {
  std::string md = fmt::format("**{}**: h_max omega by cell (h_max [s] in brackets)\n\n| ks \\ m |", integrator_name(t.kind));
  for (double m : s.masses) md += fmt::format(" {:g} kg |", m);
  md += "\n|---|";
  for (std::size_t j = 0; j < s.masses.size(); ++j) md += "---:|";
  for (std::size_t i = 0; i < t.cells.size(); ++i) {
    const GridCell& c = t.cells[i];
    if (i % s.masses.size() == 0) md += fmt::format("\n| {:g} N/m |", c.ks);
    md += c.missing.empty() ? fmt::format(" {:.6f} ({}) |", c.h_omega, sci(c.h)) : " – |";
  }
  md += fmt::format("\n\nmeasured / theory: min {:.6f}, max {:.6f}; spread over the grid (max/min - 1) {:.2e}; {} "
                    "simulation runs.",
                    t.ratio.lo(), t.ratio.hi(), t.h_omega.spread(), t.runs);
  if (!t.ratio.complete()) md += fmt::format(" Incomplete: {}.", t.ratio.reason());
  return md + bound_limited_summary(s, t) + "\n\n";
}

std::string growth_markdown(const Settings& s, const std::vector<GrowthTable>& tables) {
  std::string md = fmt::format(
      "### Explicit Euler and midpoint: no stable step, growth per period\n\n"
      "The norm r = sqrt(|x|^2 + |v|^2/omega^2) after n steps ({:g} periods, or until |x| passes the bound) gives "
      "the measured growth per step (r_n/r_0)^(1/n), raised to the 2 pi/c steps of a period; theory "
      "|R(ic)|^(2 pi/c). Range over the grid; rel. error = |ln measured / ln theory - 1|, worst cell.\n\n"
      "| integrator | c = h omega | theory growth / period | measured min | measured max | rel. error |\n"
      "|---|---:|---:|---:|---:|---:|\n",
      s.growth_periods);
  for (const GrowthTable& t : tables) {
    for (const GrowthRow& r : t.rows) {
      md += fmt::format("| {} | {:g} | {:.9g} | {:.9g} | {:.9g} | {:.1e} |\n", integrator_name(t.kind), r.c, r.theory,
                        r.growth.lo(), r.growth.hi(), r.error.hi());
      if (!r.error.complete()) md += fmt::format("| | | incomplete: {} | | | |\n", r.error.reason());
    }
  }
  return md;
}

namespace {
/// "shrinks with every longer run" or which step does not, for one grower's rows (sorted by N).
std::string shrink_verdict(const HorizonTable& t) {
  std::vector<HorizonRow> rows = t.rows;
  std::sort(rows.begin(), rows.end(), [](const HorizonRow& a, const HorizonRow& b) { return a.periods < b.periods; });
  for (std::size_t i = 0; i + 1 < rows.size(); ++i) {
    if (!std::isfinite(rows[i].measured) || !std::isfinite(rows[i + 1].measured))
      return fmt::format("{} has no value at {:g} periods", integrator_name(t.kind),
                         std::isfinite(rows[i].measured) ? rows[i + 1].periods : rows[i].periods);
    if (!(rows[i + 1].measured < rows[i].measured))
      return fmt::format("{} does not shrink from {:g} to {:g} periods", integrator_name(t.kind), rows[i].periods,
                         rows[i + 1].periods);
  }
  return fmt::format("{} shrinks with every longer run", integrator_name(t.kind));
}
}  // namespace

std::string horizon_markdown(const Settings& s, const std::vector<HorizonTable>& tables) {
  const double B = s.amplitude_bound;
  std::string md = fmt::format(
      "\nWhat the bisection reports for them depends on how long one looks: with the same definition "
      "(|x| <= {0:g}x over N periods; ks = 1 N/m, m = 1 kg) the \"largest stable step\" shrinks as N grows "
      "(Euler about ln({0:g})/(pi N), midpoint about (4 ln({0:g})/(pi N))^(1/3)). "
      "Predicted: the c at which (2 pi N/c) ln|R(ic)| = ln {0:g}.\n\n"
      "| integrator | N periods | measured h omega | predicted | measured/predicted |\n|---|---:|---:|---:|---:|\n",
      B);
  std::string verdicts;
  bool all_shrink = true;
  for (const HorizonTable& t : tables) {
    for (const HorizonRow& r : t.rows)
      md += fmt::format("| {} | {:g} | {:.5f} | {:.5f} | {:.4f} |\n", integrator_name(t.kind), r.periods, r.measured,
                        r.predicted, r.ratio);
    const std::string v = shrink_verdict(t);
    all_shrink = all_shrink && v.find("shrinks with every") != std::string::npos;
    verdicts += (verdicts.empty() ? "" : "; ") + v;
  }
  md += fmt::format("\nFrom this table: the measured step of {}{}.\n", verdicts,
                    all_shrink ? ", so no step is stable for all time" : "");
  return md;
}

std::string extremes_markdown(const std::vector<ExtremeRow>& rows, const VerdictBands& bands) {
  std::string md = "\n### Extremes\n\n| group | case | measured | verdict |\n|---|---|---|---|\n";
  for (const ExtremeRow& r : rows)
    md += fmt::format("| {} | {} | {} | {} |\n", r.group, r.label, r.measured, verdict(r, bands));
  return md + "\nDegenerate and near-degenerate triangles in self-collision are covered elsewhere.\n\n";
}

io::Json grid_data(const GridTable& t) {
  io::Json cells = io::Json::array();
  for (const GridCell& c : t.cells)
    cells.push_back({{"ks", c.ks}, {"m", c.m}, {"h_max", c.h}, {"h_omega", c.h_omega}, {"runs", c.runs}});
  return {{"theory_h_omega", t.limit}, {"ratio_min", t.ratio.lo()}, {"ratio_max", t.ratio.hi()}, {"cells", cells}};
}

io::Json growth_data(const GrowthTable& t) {
  io::Json rows = io::Json::array();
  for (const GrowthRow& r : t.rows)
    rows.push_back({{"c", r.c}, {"theory", r.theory}, {"min", r.growth.lo()}, {"max", r.growth.hi()}, {"rel_error", r.error.hi()}});
  return rows;
}

io::Json horizon_data(const HorizonTable& t) {
  io::Json rows = io::Json::array();
  for (const HorizonRow& r : t.rows) rows.push_back({{"periods", r.periods}, {"measured", r.measured}, {"predicted", r.predicted}});
  return rows;
}

}  // namespace tecido::suites::stability
