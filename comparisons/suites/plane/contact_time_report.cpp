#include "comparisons/suites/plane/contact_time_report.h"

#include "comparisons/suites/plane/theory.h"
#include "comparisons/suites/sweep.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tecido::suites::plane {

namespace {

/// Calls f(integrator index, step index, level index, cell, error) for every cell in table order.
template <class F>
void each_cell(const ContactTimeSettings& s, const ContactTable& t, F f) {
  for (std::size_t i = 0; i < s.integrators.size(); ++i)
    for (std::size_t j = 0; j < s.steps.size(); ++j)
      for (std::size_t l = 0; l < s.levels.size(); ++l) f(i, j, l, t.cells[i][j][l], t.error[i][j][l]);
}

std::string levels_words(const ContactTimeSettings& s) {
  std::string w;
  for (int k : s.levels) w += (w.empty() ? "" : ", ") + std::to_string(k);
  return w;
}

std::string steps_words(const ContactTimeSettings& s) {
  std::string w;
  for (double h : s.steps) w += (w.empty() ? "" : ", ") + fmt::format("{:g}", h);
  return w;
}

}  // namespace

std::string contact_method(const ContactTimeSettings& s) {
  return fmt::format(
      "### Time of contact by bisection (fig. 8)\n\n{} particles dropped onto the floor z = 0 under gravity g = {:g} "
      "m/s², from heights uniform in [{:g}, {:g}] m with vertical speeds uniform in [{:g}, {:g}] m/s (horizontal "
      "speeds up to {:g} m/s per axis); the time of the first contact from core's contact log against the root of "
      "z0 + vz0 t - g t²/2, at h = {} s and bisection tolerance h · 2^-k for k = {}. An integrator exact for constant "
      "acceleration (midpoint, RK4) leaves the bisection's error alone, which is checked against the tolerance; "
      "symplectic and explicit Euler add their own O(h) position error, reported. Cost: integrator calls "
      "(bisections) per contact; µs per drop: thread CPU time of the whole run to the first contact. A drop that "
      "has not touched the floor after {:g} s fails its cell's check.\n\n",
      s.drops, s.gravity, s.height_lo, s.height_hi, s.vz_lo, s.vz_hi, s.v_horizontal, steps_words(s), levels_words(s),
      s.max_time);
}

std::string contact_table(const ContactTimeSettings& s, const ContactTable& t) {
  std::string md = "| integrator | h [s] | k | tolerance [s] | max \\|t - t_exact\\| [s] | / tolerance | bisections per "
                   "contact | µs per drop |\n|---|---:|---:|---:|---:|---:|---:|---:|\n";
  each_cell(s, t, [&](std::size_t i, std::size_t j, std::size_t l, const ContactCellResult& c, const std::string& err) {
    const std::string head = fmt::format("| {} | {:g} | {} | {:.3g} |", integrator_name(s.integrators[i]), s.steps[j],
                                         s.levels[l], std::ldexp(s.steps[j], -s.levels[l]));
    const std::string why = missing_reason(s, c, err);
    if (!why.empty()) {
      md += head + fmt::format(" failed: {} | | | |\n", why);
      return;
    }
    md += head + fmt::format(" {:.3g} | {:.3g} | {:.1f} | {:.2f} |\n", c.max_error, c.max_error / c.tolerance, c.bisections,
                             1e6 * c.seconds / s.drops);
  });
  return md;
}

namespace {

/// The conclusion for an integrator exact for constant acceleration: its worst error / tolerance.
std::string exact_words(const ContactTimeSettings& s, const ContactTable& t, std::size_t i) {
  double worst = -1.0;
  std::size_t wj = 0, wl = 0;
  for (std::size_t j = 0; j < s.steps.size(); ++j)
    for (std::size_t l = 0; l < s.levels.size(); ++l) {
      const ContactCellResult& c = t.cells[i][j][l];
      if (!missing_reason(s, c, t.error[i][j][l]).empty()) continue;
      if (c.max_error / c.tolerance > worst) worst = c.max_error / c.tolerance, wj = j, wl = l;
    }
  if (worst < 0) return "no complete cell";
  return fmt::format("its largest error is {:.3g} times the bisection tolerance (h = {:g} s, k = {}), so the error {} "
                     "the tolerance down to the smallest one: the bisection's error alone",
                     worst, s.steps[wj], s.levels[wl], worst <= 1.0 ? "stays within" : "does not stay within");
}

/// The conclusion for an integrator with its own O(h) error: its error at the finest level, per step.
std::string inexact_words(const ContactTimeSettings& s, const ContactTable& t, std::size_t i) {
  const std::size_t fine = s.levels.size() - 1;
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0, over = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < s.steps.size(); ++j) {
    const ContactCellResult& c = t.cells[i][j][fine];
    if (!missing_reason(s, c, t.error[i][j][fine]).empty()) continue;
    lo = std::min(lo, c.max_error / s.steps[j]);
    hi = std::max(hi, c.max_error / s.steps[j]);
    over = std::min(over, c.max_error / c.tolerance);
  }
  if (!(hi > 0.0)) return "no complete cell at the finest tolerance";
  const std::string where = fmt::format("at k = {} its error is {:.2g} h to {:.2g} h over the steps", s.levels[fine], lo, hi);
  if (over > 2.0)
    return where + fmt::format(", at least {:.3g} times the tolerance: it stops at the integrator's own error, "
                               "which no bisection removes", over);
  return where + ": it follows the tolerance";
}

/// Bisections per contact minus the level, over every complete cell.
std::string cost_words(const ContactTimeSettings& s, const ContactTable& t) {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  each_cell(s, t, [&](std::size_t, std::size_t, std::size_t l, const ContactCellResult& c, const std::string& err) {
    if (!missing_reason(s, c, err).empty()) return;
    lo = std::min(lo, c.bisections - s.levels[l]);
    hi = std::max(hi, c.bisections - s.levels[l]);
  });
  if (!(hi >= lo)) return "";
  return fmt::format("- Cost: bisections per contact exceed k by {:.2g} to {:.2g} in every complete cell: {}.\n", lo, hi,
                     hi - lo < 1.0 ? "each extra level costs one more integrator call per contact"
                                   : "the calls per level vary by more than one");
}

}  // namespace

std::string contact_conclusions(const ContactTimeSettings& s, const ContactTable& t) {
  std::string md = "\nFrom this table:\n\n";
  for (std::size_t i = 0; i < s.integrators.size(); ++i) {
    const IntegratorKind k = s.integrators[i];
    md += fmt::format("- `{}`: {}.\n", integrator_name(k),
                      exact_for_constant_acceleration(k) ? exact_words(s, t, i) : inexact_words(s, t, i));
  }
  std::string missing;
  each_cell(s, t, [&](std::size_t i, std::size_t j, std::size_t l, const ContactCellResult& c, const std::string& err) {
    if (!missing_reason(s, c, err).empty())
      missing += fmt::format("{}{} h = {:g} k = {}", missing.empty() ? "" : ", ", integrator_name(s.integrators[i]),
                             s.steps[j], s.levels[l]);
  });
  if (!missing.empty()) md += "- Left out (failed or incomplete): " + missing + ".\n";
  return md + cost_words(s, t);
}

std::string contact_dat(const ContactTimeSettings& s, const ContactTable& t) {
  std::string dat;
  each_cell(s, t, [&](std::size_t i, std::size_t j, std::size_t, const ContactCellResult& c, const std::string& err) {
    if (missing_reason(s, c, err).empty())
      dat += fmt::format("{} {} {:.17g} {:.17g} {:.17g}\n", integrator_name(s.integrators[i]), s.steps[j], c.tolerance,
                         c.max_error, c.bisections);
  });
  return dat;
}

io::Json contact_json(const ContactTimeSettings& s, const ContactTable& t) {
  io::Json rows = io::Json::array();
  each_cell(s, t, [&](std::size_t i, std::size_t j, std::size_t l, const ContactCellResult& c, const std::string& err) {
    io::Json r = {{"integrator", integrator_name(s.integrators[i])}, {"h", s.steps[j]}, {"level", s.levels[l]}};
    if (!err.empty()) {
      r["error"] = err;
    } else {
      r.update({{"tolerance", num(c.tolerance)}, {"max_error", num(c.max_error)}, {"contacts", c.contacts},
                {"bisections_per_contact", num(c.bisections)}, {"ns_per_drop", num(1e9 * c.seconds / s.drops)}});
    }
    rows.push_back(std::move(r));
  });
  return rows;
}

}  // namespace tecido::suites::plane
