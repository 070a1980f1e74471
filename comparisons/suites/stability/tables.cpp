#include "comparisons/suites/stability/tables.h"

#include "comparisons/suites/stability/theory.h"
#include "comparisons/suites/sweep.h"

#include <fmt/format.h>

namespace tecido::suites::stability {

std::string cell_name(double ks, double m) { return fmt::format("ks = {:g} N/m, m = {:g} kg", ks, m); }

namespace {
/// The result of a case, or nullptr with `why` set to its error.
const io::Json* result_of(const Layout& l, CaseRef c, const std::vector<io::Json>& results, std::string& why) {
  const io::Json& r = results.at(case_index(l, c));
  if (const std::string* err = case_error(r)) {
    why = *err;
    return nullptr;
  }
  return &r;
}
}  // namespace

GridTable grid_table(const Settings& s, const Layout& l, std::size_t kind, const std::vector<io::Json>& results) {
  GridTable t;
  t.kind = s.bounded[kind];
  t.limit = stable_limit(t.kind);
  for (std::size_t a = 0; a < s.stiffnesses.size(); ++a) {
    for (std::size_t b = 0; b < s.masses.size(); ++b) {
      GridCell cell;
      cell.ks = s.stiffnesses[a];
      cell.m = s.masses[b];
      const std::string where = cell_name(cell.ks, cell.m);
      std::string err;
      if (const io::Json* r = result_of(l, {CaseGroup::Grid, grid_index(s, {kind, a, b})}, results, err)) {
        const StableStep st = step_from_json(*r);
        cell.runs = st.runs;
        t.runs += st.runs;
        if (st.found) {
          cell.h = st.h;
          cell.h_omega = st.h * std::sqrt(cell.ks / cell.m);
        } else {
          cell.missing = fmt::format("no stable step at {} (unstable down to h = {:.3g} s)", where, st.h_unstable);
        }
      } else {
        cell.missing = fmt::format("{}: {}", where, err);
      }
      if (cell.missing.empty()) {
        t.h_omega.add(cell.h_omega, where);
        t.ratio.add(cell.h_omega / t.limit, where);
      } else {
        t.h_omega.missing(cell.missing);
        t.ratio.missing(cell.missing);
      }
      t.cells.push_back(cell);
    }
  }
  return t;
}

GrowthTable growth_table(const Settings& s, const Layout& l, std::size_t grower, const std::vector<io::Json>& results) {
  GrowthTable t;
  t.kind = s.growers[grower];
  for (std::size_t ci = 0; ci < s.growth_cs.size(); ++ci) {
    GrowthRow row;
    row.c = s.growth_cs[ci];
    row.theory = growth_per_period(t.kind, row.c);
    for (std::size_t a = 0; a < s.stiffnesses.size(); ++a) {
      for (std::size_t b = 0; b < s.masses.size(); ++b) {
        const std::string where = fmt::format("c = {:g}, {}", row.c, cell_name(s.stiffnesses[a], s.masses[b]));
        std::string err;
        const io::Json* r = result_of(l, {CaseGroup::Growth, growth_index(s, {grower, ci, a, b})}, results, err);
        const OscillatorRun run = r ? growth_from_json(*r) : OscillatorRun{};
        if (!r || !run.finite) {
          const std::string why = r ? fmt::format("unstable at step {} ({})", run.unstable_step, where) : where + ": " + err;
          row.growth.missing(why);
          row.error.missing(why);
          continue;
        }
        const double g = std::pow(run.growth_per_step, 2.0 * kPi / row.c);
        row.growth.add(g, where);
        row.error.add(std::abs(std::log(g) / std::log(row.theory) - 1.0), where);
      }
    }
    t.worst.include(row.error);
    t.rows.push_back(row);
  }
  return t;
}

HorizonTable horizon_table(const Settings& s, const Layout& l, std::size_t grower, const std::vector<io::Json>& results) {
  HorizonTable t;
  t.kind = s.growers[grower];
  for (std::size_t n = 0; n < s.horizons.size(); ++n) {
    HorizonRow row;
    row.periods = s.horizons[n];
    row.predicted = horizon_prediction(t.kind, row.periods, s.amplitude_bound);
    const std::string where = fmt::format("{} periods", row.periods);
    std::string err;
    if (const io::Json* r = result_of(l, {CaseGroup::Horizon, horizon_index(s, {grower, n})}, results, err)) {
      const StableStep st = step_from_json(*r);
      if (st.found) {
        row.measured = st.h;  // omega = 1
        row.ratio = row.measured / row.predicted;
      } else {
        row.missing = fmt::format("no stable step over {} (unstable down to h omega = {:.3g})", where, st.h_unstable);
      }
    } else {
      row.missing = where + ": " + err;
    }
    if (row.missing.empty()) {
      t.ratio.add(row.ratio, where);
    } else {
      t.ratio.missing(row.missing);
    }
    t.rows.push_back(row);
  }
  return t;
}

}  // namespace tecido::suites::stability
