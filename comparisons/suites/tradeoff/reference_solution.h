#pragma once
/// The `tradeoff` suite's reference solution for one cloth size, and how far it can be trusted.
///
/// Five untimed runs come before the size's points: the reference (core RK4 at h_ref = h_min /
/// reference_divisor), its confirmation (RK4 at 2 h_ref), and three conditioning probes (symplectic
/// Euler at h_min from the rest shape and from nudges of every free node in and out of the cloth's
/// plane). The reference's own error is estimated by step halving (the confirmation's distance to
/// it / (2^4 - 1)); the observed order of RK4 between h_min and h_min / 2 (its error against the
/// reference, and the confirmation's) checks that the estimate's asymptotic assumption holds, the
/// consistency test by which Erez, Tassa and Todorov (2015) compare engines.
#include "comparisons/suites/tradeoff/settings.h"
#include "core/scene/scene.h"
#include "reference/guarded_run.h"

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tecido::suites::tradeoff {

/// The untimed runs of a size, in case order.
enum class Untimed { Reference, Confirmation, Probe, NudgedInPlane, NudgedOutOfPlane };
constexpr std::size_t kUntimed = 5;

/// h_min / s.reference_divisor, h_min the smallest swept step [s].
double reference_step(const std::vector<double>& swept, const Settings& s);

/// One untimed run of the n x n curtain `scene` (steps `swept`): RK4 at h_ref or 2 h_ref, or
/// symplectic Euler at h_min from the scene or from nudged(scene, substream(seed, 2n [+ 1]), ...).
reference::GuardedRun untimed_run(Untimed which, const Scene& scene, const std::vector<double>& swept,
                                  const Settings& s, std::uint64_t seed, int n);

/// What the untimed runs say about the reference.
struct ReferenceEstimate {
  std::string failure;         ///< non-empty when the reference run failed (its reason)
  double h_ref = 0.0;          ///< [s]
  double difference = NAN;     ///< RMS(confirmation - reference) [m]
  double error = NAN;          ///< the reference's estimated RMS error: difference / 15 [m]
  double order = NAN;          ///< observed RK4 order at h_min and h_min / 2
  double conditioning_in = NAN;   ///< RMS change at t = T per metre of in-plane nudge
  double conditioning_out = NAN;  ///< the same out of the plane
};

/// The estimate from the five untimed runs' positions (in Untimed order; nothing where a run
/// failed) and RK4's error at h_min against the reference (NaN when not measured).
ReferenceEstimate estimate_reference(const std::vector<std::optional<std::vector<Vec3>>>& untimed,
                                     const std::string& reference_failure, double rk4_error_at_h_min, double h_ref,
                                     const Settings& s);

}  // namespace tecido::suites::tradeoff
