#include "comparisons/suites/tradeoff/reference_solution.h"

#include "comparisons/suites/random.h"
#include "comparisons/suites/tradeoff/curtain.h"
#include "comparisons/suites/tradeoff/distances.h"
#include "comparisons/suites/tradeoff/engines.h"
#include "comparisons/suites/tradeoff/theory.h"

#include <cmath>

namespace tecido::suites::tradeoff {

double reference_step(const std::vector<double>& swept, const Settings& s) {
  return swept.back() / s.reference_divisor;
}

reference::GuardedRun untimed_run(Untimed which, const Scene& scene, const std::vector<double>& swept,
                                  const Settings& s, std::uint64_t seed, int n) {
  const TradeoffEngine rk4 = core_tradeoff_engine(IntegratorKind::RK4);
  const TradeoffEngine probe = core_tradeoff_engine(IntegratorKind::Symplectic);
  const double h_ref = reference_step(swept, s), h_min = swept.back(), T = s.seconds, L = s.stray_limit;
  const auto nth = static_cast<std::uint64_t>(n);
  switch (which) {
    case Untimed::Reference: return rk4.run_guarded(scene, h_ref, T, L);
    case Untimed::Confirmation: return rk4.run_guarded(scene, 2.0 * h_ref, T, L);
    case Untimed::Probe: return probe.run_guarded(scene, h_min, T, L);
    case Untimed::NudgedInPlane: return probe.run_guarded(nudged(scene, substream(seed, 2 * nth), false, s.nudge), h_min, T, L);
    case Untimed::NudgedOutOfPlane:
      return probe.run_guarded(nudged(scene, substream(seed, 2 * nth + 1), true, s.nudge), h_min, T, L);
  }
  return {};
}

ReferenceEstimate estimate_reference(const std::vector<std::optional<std::vector<Vec3>>>& u,
                                     const std::string& reference_failure, double rk4_error_at_h_min, double h_ref,
                                     const Settings& s) {
  ReferenceEstimate e;
  e.h_ref = h_ref;
  const auto& ref = u.at(static_cast<int>(Untimed::Reference));
  const auto& conf = u.at(static_cast<int>(Untimed::Confirmation));
  const auto& probe = u.at(static_cast<int>(Untimed::Probe));
  const auto& in = u.at(static_cast<int>(Untimed::NudgedInPlane));
  const auto& out = u.at(static_cast<int>(Untimed::NudgedOutOfPlane));
  if (!ref) e.failure = reference_failure.empty() ? "the reference run failed" : reference_failure;
  if (ref && conf) {
    e.difference = rms_distance(*conf, *ref);
    e.error = richardson_error(e.difference, 4.0);
    e.order = observed_order(rk4_error_at_h_min, e.difference);
  }
  if (probe && in) e.conditioning_in = rms_distance(*probe, *in) / s.nudge;
  if (probe && out) e.conditioning_out = rms_distance(*probe, *out) / s.nudge;
  return e;
}

}  // namespace tecido::suites::tradeoff
