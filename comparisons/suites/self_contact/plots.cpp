#include "comparisons/suites/self_contact/plots.h"

#include "comparisons/io/atomic_file.h"
#include "comparisons/io/gnuplot.h"

#include <fmt/format.h>

#include <cmath>

namespace tecido::suites::self_contact {

namespace {

std::string field(double x) { return std::isfinite(x) ? fmt::format("{:.17g}", x) : "?"; }

std::string cells_data(const Plan& plan, const Findings& f) {
  std::vector<std::vector<CellStats>> by_d;
  for (std::size_t d = 0; d < plan.detectors.size(); ++d) by_d.push_back(baseline_cells(plan, f, d));
  std::string dat = "# cell seed_value then per detector: mean ci_lo ci_hi\n";
  for (int c = 0; c < CellGrid::kCells; ++c) {
    dat += fmt::format("{} {}", c, field(plan.seed.share[c]));
    for (const auto& cells : by_d) dat += fmt::format(" {} {} {}", field(cells[c].s.mean), field(cells[c].s.ci95.lo), field(cells[c].s.ci95.hi));
    dat += "\n";
  }
  return dat;
}

std::string effects_data(const Plan& plan, const Findings& f) {
  std::string dat = "# mode, then in percent: seed_mean seed_lo seed_hi, per detector: mean ci_lo ci_hi\n";
  for (int m = 1; m < CellGrid::kModes; ++m) {
    const SeedEffect se = seed_effect(plan.seed, mode_pairs(m));
    dat += fmt::format("{} {} {} {}", m, field(100 * se.s.mean), field(100 * se.s.ci95.lo), field(100 * se.s.ci95.hi));
    for (std::size_t d = 0; d < plan.detectors.size(); ++d) {
      const Effect e = relative_effect(f.ensembles[0], d, mode_pairs(m));
      dat += fmt::format(" {} {} {}", field(100 * e.s.mean), field(100 * e.s.ci95.lo), field(100 * e.s.ci95.hi));
    }
    dat += "\n";
  }
  return dat;
}

/// "plot" clauses: the seed's (`seed_clause`: columns and style), then each detector's error bars
/// from column `first` on (mean, lo, hi per detector), shifted `step` apart.
std::string series(const Plan& plan, const char* file, const std::string& seed_clause, std::size_t first, double step) {
  std::string s = fmt::format("'{}' using {} title \"the seed's\"", file, seed_clause);
  for (std::size_t d = 0; d < plan.detectors.size(); ++d) {
    const std::size_t col = first + 3 * d;
    s += fmt::format(", '{}' using ($1+{}):{}:{}:{} title 'ours, {}' with yerrorbars pt 7 ps 0.5", file, step * (d + 1), col,
                     col + 1, col + 2, contact_test_name(plan.detectors[d]));
  }
  return s;
}

bool draw(const Plan& plan, const char* name, const std::string& body) {
  const std::string script = fmt::format(
      "set terminal svg size 1000,420 dynamic font 'sans,11'\nset output '{}.svg'\nset datafile missing '?'\nset grid\n"
      "set key outside right\n{}\n", name, body);
  return io::run_gnuplot(plan.opt.out_dir, name, script);
}

}  // namespace

std::string plots_section(const Plan& plan, const Findings& f) {
  if (plan.opt.out_dir.empty()) return "";
  io::write_file_atomic(plan.opt.out_dir + "/experiment_cells.dat", cells_data(plan, f));
  io::write_file_atomic(plan.opt.out_dir + "/experiment_effects.dat", effects_data(plan, f));
  std::string md = "## Plots\n\n";
  if (!io::gnuplot_available()) return md + "gnuplot not found: the data are in experiment_cells.dat and experiment_effects.dat.\n\n";
  const bool cells = draw(plan, "experiment_cells",
                          "set xlabel 'cell index ((wind x 3 + step) x 2 + elasticity) x 4 + mode'\nset ylabel 'share of frames "
                          "with self-contact'\nset xrange [-1:72]\nplot " +
                              series(plan, "experiment_cells.dat", "1:2 with points pt 2 ps 0.8", 3, 0.2));
  const bool effects = draw(plan, "experiment_effects",
                            "set xlabel 'edge mode'\nset ylabel 'relative change against no response'\nset xrange [0.5:3.9]\n"
                            "set xtics 1\nset format y '%.0f%%'\nplot " +
                                series(plan, "experiment_effects.dat", "1:2:3:4 with yerrorbars pt 2 ps 1", 5, 0.15));
  if (cells) md += "![every cell's mean share with its 95% interval, beside the seed's value](experiment_cells.svg)\n\n";
  if (effects) md += "![relative change of each mode with 95% intervals, beside the seed's](experiment_effects.svg)\n\n";
  return md;
}

}  // namespace tecido::suites::self_contact
