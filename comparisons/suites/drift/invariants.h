#pragma once
/// The `drift` suite's invariants analysis: one integrator on one conservative scene for a long
/// run, with the energy, momentum and angular momentum errors it reports and checks.
///
/// Definitions (the report prints them):
///  - relative energy error |E(t) - E0| / E0, E = kinetic + spring potential energy;
///  - growth rate: least-squares slope of that error against time [1/s];
///  - last/first half: the largest error of the run's second half over that of its first half
///    (about 1 when the error oscillates without trend, above 1 when it grows);
///  - momentum error: max over samples of |P(t) - P0| / max(sum m|v0|, sum m|v(t)|), P = sum m v:
///    the round-off of a sum of momenta scales with the momenta summed, now or at the start;
///  - angular momentum error: max over samples of |L(t) - L0| / max(sum m|x0||v0|, sum m|x(t)||v(t)|),
///    L = sum m x x v about the origin;
///  - angular momentum against theory: the same with L(t) - L0 replaced by L(t) - L0 minus the
///    change theory.h predicts, summed step by step (zero for symplectic Euler).
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/drift/settings.h"
#include "core/dynamics/integrator.h"
#include "core/scene/scene.h"

#include <array>
#include <string>
#include <vector>

namespace tecido::suites::drift {

/// Kinetic plus spring potential energy [J].
double energy(const Scene& scene, const std::vector<Vec3>& x, const std::vector<Vec3>& v);
/// sum m v over free particles [kg m/s].
Vec3 momentum(const std::vector<double>& inv_mass, const std::vector<Vec3>& v);
/// sum m x x v over free particles, about the origin [kg m^2/s].
Vec3 angular_momentum(const std::vector<double>& inv_mass, const std::vector<Vec3>& x, const std::vector<Vec3>& v);
/// sum m |v| and sum m |x| |v| over free particles: the scales the two errors are divided by.
double momentum_scale(const std::vector<double>& inv_mass, const std::vector<Vec3>& v);
double angular_momentum_scale(const std::vector<double>& inv_mass, const std::vector<Vec3>& x,
                              const std::vector<Vec3>& v);

/// One run's measurements (the definitions above).
struct InvariantRun {
  long long steps = 0;               ///< steps asked for
  long long unstable_at_step = 0;    ///< 1-based step at which the state stopped being finite (0: never)
  double final_rel_energy = 0.0;     ///< at the last sample
  double max_rel_energy = 0.0;
  double growth_rate = 0.0;          ///< [1/s]
  double last_over_first_half = 0.0;
  double momentum_error = 0.0;
  double angular_momentum_error = 0.0;
  double angular_momentum_vs_theory = 0.0;  ///< equals angular_momentum_error for symplectic Euler
  std::vector<std::array<double, 2>> energy_curve;  ///< (t, relative energy error) every plot_every steps
};

/// The running statistics of one run, fed a sample at a time: built on the initial state, given
/// the state after step i (time t) with the angular momentum change theory predicts up to it
/// (zero when it predicts none), finished into the run's measurements.
struct InvariantTally {
  const Scene& scene;
  long long steps;
  double e0 = 0.0, p_scale0 = 0.0, l_scale0 = 0.0;
  Vec3 p0 = Vec3::Zero(), l0 = Vec3::Zero();
  double first_half = 0.0, second_half = 0.0;
  double st = 0, se = 0, stt = 0, ste = 0;
  long long n = 0;
  InvariantRun r;

  InvariantTally(const Scene& s, long long steps);
  void sample(long long i, double t, const std::vector<Vec3>& x, const std::vector<Vec3>& v, const Vec3& dl_theory,
              bool plot);
  InvariantRun finish();
};

/// Runs core with `kind` on `scene` for s.steps steps (stopping at an unstable step), sampling
/// every s.sample_every steps; the angular momentum theory is summed over every step.
InvariantRun run_invariants(const Scene& scene, IntegratorKind kind, const Settings& s);

/// The run as JSON (lossless, NaN and infinities included) and back.
io::Json invariant_json(const InvariantRun& r);
InvariantRun invariant_from_json(const io::Json& j);

}  // namespace tecido::suites::drift
