#include "comparisons/suites/stability/outside_stability.h"

#include "comparisons/suites/stability/cases.h"
#include "comparisons/suites/stability/value_range.h"
#include "comparisons/suites/sweep.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tecido::suites::stability {

OutsidePlan outside_plan(const Settings& s, std::vector<outside::OutsideEnginePtr> engines) {
  OutsidePlan p;
  p.engines = std::move(engines);
  p.settings = s.outside;
  p.amplitude_bound = s.amplitude_bound;
  p.rel_tol = s.rel_tol;
  return p;
}

bool outside_stable(outside::OutsideEngine& engine, double ks, double m, double h, double periods, double bound) {
  const double omega = std::sqrt(ks / m);
  outside::Creation c = engine.create(oscillator_scene(IntegratorKind::Symplectic, ks, m, h));
  if (!c.simulation) throw std::runtime_error(outside::not_modelled_line(engine.name(), c.refusal));
  const long long n = steps_for(periods, omega, h), per_period = std::max(1LL, steps_for(1.0, omega, h));
  for (long long done = 0; done < n;) {
    const long long k = std::min(per_period, n - done);
    if (!c.simulation->advance(k)) return false;
    done += k;
    if (!(c.simulation->positions()[1].norm() <= bound)) return false;
  }
  return true;
}

namespace {

struct Cell {
  std::size_t engine, ks, m;
};

Cell cell_at(const OutsidePlan& plan, std::size_t i) {
  const std::size_t nm = plan.settings.masses.size(), cells = plan.cells();
  return {i / cells, (i % cells) / nm, i % nm};
}

std::string where(double ks, double m) { return fmt::format("ks = {:g} N/m, m = {:g} kg", ks, m); }

}  // namespace

io::Json run_outside_case(const OutsidePlan& plan, std::size_t i) {
  const Cell c = cell_at(plan, i);
  outside::OutsideEngine& engine = *plan.engines.at(c.engine);
  const double ks = plan.settings.stiffnesses[c.ks], m = plan.settings.masses[c.m], omega = std::sqrt(ks / m);
  const StableStep st = find_max_stable_step(
      [&](double h) { return outside_stable(engine, ks, m, h, plan.settings.periods, plan.amplitude_bound); },
      1.0 / omega, plan.rel_tol, 20, plan.settings.max_halvings);
  return step_json(st);
}

std::string outside_check_name(const std::string& engine) { return "stability/" + engine + "/grid_spread"; }

void declare_outside_checks(CheckList& checks, const OutsidePlan& plan, const Tolerances& tol) {
  for (const auto& e : plan.engines)
    checks.declare(outside_check_name(e->name()), tol.at_most("/stability/grid_spread"),
                   "max/min - 1 of h_max omega over the cells (outside engine " + e->name() + ")");
}

std::string outside_tables(const OutsidePlan& plan, const std::vector<io::Json>& results, CheckList& checks,
                           io::Json& data) {
  if (plan.engines.empty()) return "";
  const OutsideSettings& s = plan.settings;
  std::string md = fmt::format(
      "### Outside engines: largest stable step\n\nh_max omega of each outside engine on the oscillator, per cell "
      "(stiffness x mass), by the same bisection; a run of {:g} periods is stable while finite and within {:g} x the "
      "initial amplitude at the end of every period (one call of the engine's door per period). No stable step down "
      "to 2^-{} / omega: –. Checked: the spread over the cells, as for core's integrators.\n\n| engine |",
      s.periods, plan.amplitude_bound, s.max_halvings);
  std::string doors;
  for (const auto& e : plan.engines) doors += "- " + e->name() + ": " + e->door() + "\n";
  md.insert(md.find("| engine |"), doors + "\n");
  std::string rule = "|---|";
  for (double ks : s.stiffnesses)
    for (double m : s.masses) md += fmt::format(" {:g}/{:g} |", ks, m), rule += "---:|";
  md += " spread |\n" + rule + "---:|\n";
  for (std::size_t e = 0; e < plan.engines.size(); ++e) {
    const std::string& name = plan.engines[e]->name();
    ValueRange range;
    md += "| " + name + " |";
    for (std::size_t k = 0; k < plan.cells(); ++k) {
      const Cell c = cell_at(plan, e * plan.cells() + k);
      const double ks = s.stiffnesses[c.ks], m = s.masses[c.m];
      const io::Json& r = results.at(e * plan.cells() + k);
      if (const std::string* err = case_error(r)) {
        range.missing(where(ks, m) + ": " + *err);
        md += " failed |";
        continue;
      }
      const StableStep st = step_from_json(r);
      const double hw = st.h * std::sqrt(ks / m);
      if (!st.found) range.missing("no stable step at " + where(ks, m));
      else range.add(hw, where(ks, m));
      md += st.found ? fmt::format(" {:.6g} |", hw) : " – |";
      data["outside"][name].push_back({{"ks", ks}, {"m", m}, {"h_omega", st.found ? io::Json(hw) : io::Json(nullptr)}});
    }
    record(checks, outside_check_name(name), range, range.spread());
    md += range.complete() ? fmt::format(" {:.2g} |\n", range.spread()) : " – |\n";
    if (!range.complete()) md += "\n" + name + ": " + range.reason() + "\n\n";
  }
  return md + "\n";
}

}  // namespace tecido::suites::stability
