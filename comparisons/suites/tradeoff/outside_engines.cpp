#include "comparisons/suites/tradeoff/outside_engines.h"

#include "comparisons/engines/dynamics_engines.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tecido::suites::tradeoff {

TradeoffEngine outside_tradeoff_engine(const outside::OutsideEnginePtr& engine, const Settings& s) {
  return tradeoff_engine(engines::outside_dynamics_entry(engine), s);
}

std::string outside_check_name(int n, const std::string& engine) {
  return fmt::format("tradeoff/{}/{}/reproducible", n, engine);
}

void declare_outside_checks(CheckList& checks, const Settings& s, const std::vector<TradeoffEngine>& engines,
                            const Tolerances& tol) {
  for (const Size& z : s.sizes)
    for (const TradeoffEngine& e : engines)
      if (!e.door.empty() && !skipped(e, z.n, 0))
        checks.declare(outside_check_name(z.n, e.name), tol.at_most("/tradeoff/reproducible_max_abs_diff"),
                       "max over its points of the rerun's max |x - x_rerun| [m] (outside engine " + e.name + ")");
}

void record_outside_checks(CheckList& checks, const SizeAnalysis& a, const std::vector<TradeoffEngine>& engines) {
  for (std::size_t e = 0; e < engines.size(); ++e) {
    const std::string name = outside_check_name(a.n, engines[e].name);
    if (!checks.declared(name)) continue;
    double worst = -1.0;
    std::string statuses;
    for (const Point& p : a.points) {
      if (p.engine != e) continue;
      if (!p.x.empty()) worst = std::max(worst, p.rerun_diff);
      else statuses += (statuses.empty() ? "" : "; ") + h_label(p.h) + ": " + p.status;
    }
    if (worst >= 0.0) checks.set(name, worst);
    else checks.fail(name, "no run returned positions (" + statuses + ")");
  }
}

std::string outside_markdown(const std::vector<TradeoffEngine>& engines) {
  std::string list;
  for (const TradeoffEngine& e : engines)
    if (!e.door.empty())
      list += fmt::format("- {}: {}; cloths up to {}^2 nodes, {}\n", e.name, e.door, e.max_n,
                          e.max_steps > 0 ? fmt::format("the {} largest steps", e.max_steps) : "every swept step");
  if (list.empty()) return "";
  return fmt::format(
      "#### Outside engines\n\n{}\nAn outside engine's cost is the wall time of its run, door included: it takes {} "
      "steps per call of its door, and for a process each call is a round trip through its pipes (the request and the "
      "positions and velocities back as JSON) besides the process's own stepping. Its points stand on the same plane "
      "as core's and Bullet's, but the cost of the door is part of them. Checked: a rerun through the door returns the "
      "same nodes (the largest rerun difference of its points).\n\n",
      list, kOutsideChunk);
}

}  // namespace tecido::suites::tradeoff
