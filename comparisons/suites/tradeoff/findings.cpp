#include "comparisons/suites/tradeoff/findings.h"

#include "comparisons/suites/tradeoff/theory.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tecido::suites::tradeoff {

namespace {

/// The range of the finite values added.
struct Range {
  double lo = INFINITY, hi = -INFINITY;
  void add(double x) {
    if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
  }
  bool empty() const { return lo > hi; }
  std::string text(const char* f = "{:.3g}") const {
    if (empty()) return "not measured";
    const std::string a = fmt::format(fmt::runtime(f), lo), b = fmt::format(fmt::runtime(f), hi);
    return a == b ? a : a + " to " + b;
  }
};

bool has_engine(const std::vector<TradeoffEngine>& engines, const std::string& name) {
  return std::any_of(engines.begin(), engines.end(), [&](const TradeoffEngine& e) { return e.name == name; });
}

std::string deformable_paragraph(const std::vector<SizeAnalysis>& sizes, const std::vector<TradeoffEngine>& engines) {
  Range distance, cost_ratio;
  std::string fronts;
  for (const SizeAnalysis& a : sizes) {
    distance.add(engines_distance(a, engines, "bullet-deformable", "core-symplectic"));
    for (std::size_t j = 0; j < a.swept.size(); ++j) {
      const Point *b = point_at(a, engines, "bullet-deformable", j), *c = point_at(a, engines, "core-symplectic", j);
      if (b && c) cost_ratio.add(b->cost / c->cost);
      if (on_front(a, b)) fronts += fmt::format("{}{}^2 at {}", fronts.empty() ? "" : ", ", a.n, h_label(b->h));
    }
  }
  return fmt::format(
      "`bullet-deformable` is the deformable world in explicit mode, the same model (Hooke springs, masses, pins) and "
      "the same integrator as `core-symplectic`: at equal steps its final positions differ from core's by at most {} m "
      "RMS, and a run costs {} times core's; it is on {}. Its solver iterations do not change an undamped explicit step "
      "(the mass-preconditioned solve converges in one), so it has one entry.\n\n",
      distance.empty() ? std::string("(not measured)") : fmt::format("{:.2g}", distance.hi), cost_ratio.text("{:.3g}"),
      fronts.empty() ? "no front" : "the front at " + fronts);
}

std::string implicit_paragraph(const std::vector<SizeAnalysis>& sizes, const std::vector<TradeoffEngine>& engines) {
  Range order, iterations;
  for (const SizeAnalysis& a : sizes) {
    for (const char* name : {"bullet-deformable-implicit-it1", "bullet-deformable-implicit-it4", "bullet-deformable-implicit-it16"})
      for (std::size_t j = 0; j + 1 < a.swept.size(); ++j) {
        const Point *p = point_at(a, engines, name, j), *q = point_at(a, engines, name, j + 1);
        if (p && q) order.add(observed_order(p->error, q->error));
      }
    for (std::size_t j = 0; j < a.swept.size(); ++j) {
      const Point *p1 = point_at(a, engines, "bullet-deformable-implicit-it1", j),
                  *p16 = point_at(a, engines, "bullet-deformable-implicit-it16", j);
      if (p1 && p16) iterations.add(p16->error / p1->error);
    }
  }
  std::string verdict;
  if (!iterations.empty())
    verdict = iterations.lo >= 0.9 ? ": more iterations buy no accuracy (an inexact solve damps less)"
                                   : ": more iterations reduce the error";
  return fmt::format(
      "`bullet-deformable-implicit-itK` is the same world in implicit mode (Newton on a linearised backward-Euler step) "
      "with each conjugate-gradient solve capped at K iterations: damped, its observed order between neighbouring "
      "steps is {}, and at each step its error with 16 iterations is {} times that with 1{}.\n\n",
      order.text("{:.2f}"), iterations.text("{:.2f}"), verdict);
}

std::string classic_paragraph(const std::vector<SizeAnalysis>& sizes, const std::vector<TradeoffEngine>& engines,
                              const Settings& s) {
  std::string md = fmt::format(
      "`bullet-classic-itK` is the classic soft body with K position-solver sweeps: its links are position "
      "constraints, not springs, so its stiffness kLST is calibrated for every cloth, step and K until its static sag "
      "matches core's within {:g} % (calibrate_klst_for_sag, started from an h^2 / K scaling law, cached per cloth, "
      "step and K); the calibration runs in an untimed first call of each point, so the costs are of stepping only. "
      "Its error against the RK4 reference measures how far a position-based model is from the spring model as much "
      "as integration error:",
      100.0 * s.classic.relative_tolerance);
  const char* names[] = {"bullet-classic-it1", "bullet-classic-it4", "bullet-classic-it16"};
  for (const SizeAnalysis& a : sizes) {
    Range first, last, spread_max;
    std::size_t j_last = 0;
    for (const char* name : names)
      for (std::size_t j = 0; j < a.swept.size(); ++j)
        if (point_at(a, engines, name, j)) j_last = std::max(j_last, j);
    for (std::size_t j = 0; j <= j_last; ++j) {
      Range at;
      for (const char* name : names)
        if (const Point* p = point_at(a, engines, name, j)) at.add(p->error);
      if (j == 0) first = at;
      if (j == j_last) last = at;
      if (!at.empty()) spread_max.add(at.hi / at.lo - 1.0);
    }
    if (first.empty()) continue;
    md += fmt::format(" on the {}^2 cloth it is {} m at h0 and {} m at {} across 1, 4 and 16 sweeps; at each step the "
                      "sweep counts' errors differ by at most {:.0f} %{}.",
                      a.n, first.text(), last.text(), h_label(a.swept[j_last]), 100.0 * spread_max.hi,
                      spread_max.hi < 0.25 ? ", so the number of sweeps hardly matters" : "");
  }
  return md + "\n";
}

}  // namespace

std::string core_findings(const std::vector<SizeAnalysis>& sizes, const std::vector<TradeoffEngine>& engines) {
  std::string steps, counted;
  for (const SizeAnalysis& a : sizes) steps += fmt::format("{}{}^2: {}", steps.empty() ? "" : ", ", a.n, h_label(a.swept.front()));
  for (const char* name : {"core-euler", "core-midpoint"}) {
    std::string per;
    for (const SizeAnalysis& a : sizes) {
      const Point* best = nullptr;
      for (std::size_t j = 0; j < a.swept.size() && !best; ++j) {
        const Point* p = point_at(a, engines, name, j);
        if (p && p->counted) best = p;
      }
      per += fmt::format("{}{}^2 {}", per.empty() ? "" : ", ", a.n, best ? h_label(best->h) : "none");
    }
    counted += fmt::format("{}`{}`: {}", counted.empty() ? "" : "; ", name, per);
  }
  return fmt::format(
      "The first swept step h0 falls as the springs' highest frequency grows with the node count at fixed size and "
      "material ({}). Explicit Euler and midpoint amplify undamped oscillations at every step (see the stability "
      "suite), so near symplectic Euler's limit they blow up; the largest step at which each counted here: {}.\n\n",
      steps, counted);
}

std::string bullet_findings(const std::vector<SizeAnalysis>& sizes, const std::vector<TradeoffEngine>& engines,
                            const Settings& s) {
  if (!has_engine(engines, "bullet-deformable"))
    return "Bullet's engines are not among the engines run.\n";
  const BulletRange& r = s.bullet;
  return fmt::format("Bullet 3.24 (double build) joins the comparison in both kinds. To keep the suite's time within "
                     "bounds its engines run only on cloths of at most {}^2 nodes ({}^2 for the implicit, {}^2 for the "
                     "classic ones) and at the {} largest swept steps; the points outside are not run.\n\n",
                     r.max_side_explicit, r.max_side_implicit, r.max_side_classic, r.max_steps) +
         deformable_paragraph(sizes, engines) + implicit_paragraph(sizes, engines) + classic_paragraph(sizes, engines, s);
}

}  // namespace tecido::suites::tradeoff
