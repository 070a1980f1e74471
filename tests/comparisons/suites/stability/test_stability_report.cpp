// The stability suite's report (comparisons/suites/stability/stability_report.*): figures follow the
// settings, and each conclusion follows the table it summarises (planted tables that contradict it
// change what the prose says).
#include "comparisons/suites/stability/stability_report.h"
#include "comparisons/suites/stability/theory.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::suites::stability {
namespace {

bool contains_text(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(StabilityReport, TheTheoryParagraphFollowsTheBound) {
  Settings s = settings(true);
  s.amplitude_bound = 50.0;
  // 2 sqrt(1 - 1/2500) = 2 sqrt(0.9996) = 1.99959996; the 10x illustration 2 sqrt(0.99) = 1.98997.
  const std::string md = method_markdown(s);
  EXPECT_TRUE(contains_text(md, "a bound of 50x puts the measured limit at 2 sqrt(1 - 1/50^2) = 1.9996000")) << md;
  EXPECT_TRUE(contains_text(md, "would have stopped it at 1.990")) << md;
  EXPECT_TRUE(contains_text(md, "over 1000 periods")) << md;
  EXPECT_TRUE(contains_text(settings_markdown(s), "within 50x the initial amplitude"));
  EXPECT_TRUE(contains_text(grid_heading(s), "symplectic 2, rk4 2.828"));
}

GridTable symplectic_grid(double h_omega_a, double h_omega_b) {
  GridTable t;
  t.kind = IntegratorKind::Symplectic;
  t.limit = 2.0;
  for (double c : {h_omega_a, h_omega_b}) {
    GridCell cell;
    cell.ks = 1.0;
    cell.m = c == h_omega_a ? 1.0 : 2.0;
    cell.h_omega = c;
    cell.h = c;
    t.cells.push_back(cell);
    t.h_omega.add(c, "");
    t.ratio.add(c / 2.0, "");
  }
  return t;
}

TEST(StabilityReport, TheBoundLimitedSummaryComparesWithTheBracket) {
  Settings s = settings(true);
  s.masses = {1.0, 2.0};
  const double pred = bound_stretch_limit(s.amplitude_bound);
  EXPECT_TRUE(contains_text(grid_markdown(s, symplectic_grid(pred, pred * (1 - 5e-7))), "inside the bisection's bracket"));
  EXPECT_TRUE(contains_text(grid_markdown(s, symplectic_grid(pred, pred * (1 - 1e-3))), "outside the bisection's bracket"));
}

TEST(StabilityReport, AMissingCellIsShownAndNamed) {
  Settings s = settings(true);
  s.masses = {1.0, 2.0};
  GridTable t = symplectic_grid(1.9, 1.95);
  t.cells[1].missing = "no stable step at ks = 1 N/m, m = 2 kg";
  t.ratio.missing(t.cells[1].missing);
  t.h_omega.missing(t.cells[1].missing);
  const std::string md = grid_markdown(s, t);
  EXPECT_TRUE(contains_text(md, "| – |")) << md;
  EXPECT_TRUE(contains_text(md, "Incomplete: no stable step at ks = 1 N/m, m = 2 kg.")) << md;
}

HorizonTable horizons(IntegratorKind k, std::vector<double> measured) {
  HorizonTable t;
  t.kind = k;
  const double periods[] = {10, 30, 100};
  for (std::size_t i = 0; i < measured.size(); ++i) {
    HorizonRow r;
    r.periods = periods[i];
    r.measured = measured[i];
    t.rows.push_back(r);
  }
  return t;
}

TEST(StabilityReport, TheHorizonConclusionFollowsItsTable) {
  const Settings s = settings(true);
  const std::string shrinking = horizon_markdown(
      s, {horizons(IntegratorKind::Euler, {0.2, 0.07, 0.02}), horizons(IntegratorKind::Midpoint, {1.0, 0.7, 0.4})});
  EXPECT_TRUE(contains_text(shrinking, "euler shrinks with every longer run; midpoint shrinks with every longer run, so no step "
                             "is stable for all time"))
      << shrinking;
  const std::string flat = horizon_markdown(
      s, {horizons(IntegratorKind::Euler, {0.2, 0.07, 0.02}), horizons(IntegratorKind::Midpoint, {1.0, 1.0, 0.4})});
  EXPECT_TRUE(contains_text(flat, "midpoint does not shrink from 10 to 30 periods")) << flat;
  EXPECT_FALSE(contains_text(flat, "for all time")) << flat;
  const std::string missing = horizon_markdown(s, {horizons(IntegratorKind::Euler, {0.2, NAN, 0.02})});
  EXPECT_TRUE(contains_text(missing, "euler has no value at 30 periods")) << missing;
  EXPECT_FALSE(contains_text(missing, "for all time")) << missing;
}

TEST(StabilityReport, ExtremesRowsShowTheJudgedVerdict) {
  const VerdictBands bands = {{"rest_jitter", Band{0.0, 1e-12, "/stability/rest_max_jitter"}}};
  const std::vector<ExtremeRow> rows = {
      {"resting contact", "a", "m", "", ExtremeRow::Judge{"rest_jitter", {0.0}, "ok: still", "degraded: jitters"}},
      {"resting contact", "b", "m", "", ExtremeRow::Judge{"rest_jitter", {1e-9}, "ok: still", "degraded: jitters"}}};
  const std::string md = extremes_markdown(rows, bands);
  EXPECT_TRUE(contains_text(md, "| resting contact | a | m | ok: still |")) << md;
  EXPECT_TRUE(contains_text(md, "| resting contact | b | m | degraded: jitters |")) << md;
}

}  // namespace
}  // namespace tecido::suites::stability
