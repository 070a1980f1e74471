#include "comparisons/suites/tradeoff/cases.h"

#include "comparisons/suites/sweep.h"
#include "comparisons/suites/tradeoff/distances.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <stdexcept>

namespace tecido::suites::tradeoff {

CaseLayout case_layout(const std::vector<Size>& sizes, std::size_t engines) {
  CaseLayout l;
  l.sizes = sizes;
  l.engines = engines;
  for (const Size& sz : sizes) {
    l.first.push_back(l.cases);
    l.cases += kUntimed + engines * static_cast<std::size_t>(sz.steps);
  }
  return l;
}

CaseIndex CaseLayout::locate(std::size_t k) const {
  if (k >= cases) throw std::out_of_range("tradeoff case " + std::to_string(k) + " of " + std::to_string(cases));
  CaseIndex c;
  while (c.size + 1 < sizes.size() && k >= first[c.size + 1]) ++c.size;
  const std::size_t local = k - first[c.size];
  if (local < kUntimed) {
    c.untimed = static_cast<Untimed>(local);
    return c;
  }
  c.timed = true;
  c.engine = (local - kUntimed) / static_cast<std::size_t>(sizes[c.size].steps);
  c.step = (local - kUntimed) % static_cast<std::size_t>(sizes[c.size].steps);
  return c;
}

io::Json run_json(const reference::GuardedRun& r) {
  return {{"x", r.x ? vec3s_json(*r.x) : io::Json(nullptr)}, {"reason", r.reason}};
}

std::optional<std::vector<Vec3>> positions_of(const io::Json& result) {
  const io::Json& x = result.at("x");
  if (x.is_null()) return std::nullopt;
  return vec3s_from_json(x);
}

io::Json untimed_case(Untimed which, const Scene& scene, const std::vector<double>& swept, const Settings& s,
                      std::uint64_t seed, int n) {
  return run_json(untimed_run(which, scene, swept, s, seed, n));
}

Timed timed_run(const TradeoffEngine& e, const Scene& scene, double h, const Settings& s) {
  using clock = std::chrono::steady_clock;
  Timed t;
  t.run = e.run_guarded(scene, h, s.seconds, s.stray_limit);
  double total = 0.0;
  t.seconds = std::numeric_limits<double>::infinity();
  do {
    const auto t0 = clock::now();
    const reference::GuardedRun again = e.run_guarded(scene, h, s.seconds, s.stray_limit);
    const double secs = std::chrono::duration<double>(clock::now() - t0).count();
    total += secs;
    t.seconds = std::min(t.seconds, secs);
    if (t.repeats == 0 && t.run.x && again.x) t.rerun_diff = max_abs_difference(*t.run.x, *again.x);
    ++t.repeats;
  } while (t.run.x && t.seconds < s.timing_min_seconds && total < s.timing_max_total && t.repeats < s.timing_max_repeats);
  return t;
}

io::Json point_case(const TradeoffEngine& e, const Scene& scene, int n, std::size_t j, double h, const Settings& s) {
  if (skipped(e, n, j)) return {{"skipped", true}};
  const Timed t = timed_run(e, scene, h, s);
  io::Json r = run_json(t.run);
  r["seconds"] = num(t.seconds);
  r["rerun_diff"] = num(t.rerun_diff);
  return r;
}

}  // namespace tecido::suites::tradeoff
