#pragma once
/// Suite `tradeoff`: what each bit of accuracy costs. A hanging cloth (n x n nodes, n = 16..128,
/// pinned at two corners, under gravity, no planes) is simulated for 1 s by every engine in
/// tradeoff_engines() at a few halvings of the step. Each stable run is a point (cost = wall
/// seconds per simulated second, error = RMS node distance at t = 1 s to a converged reference:
/// core RK4 at a quarter of the smallest swept step, confirmed by step halving, as Erez, Tassa and
/// Todorov (2015) judge engines by their consistency across step sizes), after checking that the
/// scene is well-conditioned (a 1e-12 m nudge at t = 0 stays small at t = 1 s). It reports the
/// Pareto front (no other point is both cheaper and more accurate), plots cost against error,
/// and reruns every front point to check that it is bit-for-bit reproducible.
#include "comparisons/suites/suite.h"
#include "comparisons/suites/sweep.h"
#include "core/scene/scene.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace tecido::suites {

/// A dynamics engine as the tradeoff suite sees it: simulate `scene` (its own integrator and dt
/// are ignored) from t = 0 to `seconds` at step h and return every particle's position in core's
/// numbering, or nothing when the run became unstable (NaN/Inf or diverged).
struct TradeoffEngine {
  std::string name;                   ///< e.g. "core-rk4"
  double evaluations_per_step = 0.0;  ///< force evaluations per step, for the report (0 = unknown)
  std::function<std::optional<std::vector<Vec3>>(const Scene& scene, double h, double seconds)> run;
  /// The suite runs this engine only on cloths of at most max_n x max_n nodes and at the
  /// max_steps largest swept steps (0 = no limit): the points outside are skipped, not listed.
  int max_n = 0;
  int max_steps = 0;
};

/// The engines the suite compares, in report order: core's euler, symplectic, midpoint and rk4.
/// Another engine (Bullet's soft body, say) is one more entry appended to this list.
std::vector<TradeoffEngine> tradeoff_engines();

/// Core with integrator `kind` as a tradeoff engine. A run is abandoned (nothing returned) at the
/// first non-finite step or when a node strays more than 1e3 m from its start (checked every 64
/// steps and at the end).
TradeoffEngine core_tradeoff_engine(IntegratorKind kind);

/// One point of the cost/error plane.
struct CostError {
  double cost = 0.0;
  double error = 0.0;
};

/// Indices of the Pareto front of `pts`, lower cost and lower error being better: the points that
/// no other point dominates (dominates = no worse in both, strictly better in at least one).
/// Points with a non-finite coordinate are neither on the front nor dominate. Equal points are all
/// kept. Sorted by increasing cost, ties by increasing error, then by index.
std::vector<int> pareto_front(const std::vector<CostError>& pts);

/// RMS over particles of |a_i - b_i| (the vectors must have equal sizes); NaN when empty.
double rms_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b);

/// Max over particles and coordinates of |a_i - b_i| (0 when bit-identical and finite).
double max_abs_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b);

/// The suite's scene, a curtain: an n x n cloth, 1 m x 1 m, hanging in the vertical plane y = 0
/// (origin at the top-left node, columns along +x, rows down along -z), released at rest from its
/// rest shape, pinned at its top corners (row 0, col 0) and (row 0, col n-1), total mass 0.1 kg,
/// type B springs 1 N/m, type A springs 0.5 N/m, no damping, gravity (0, 0, -9.81) m/s^2, no
/// planes. Gravity lies in the cloth's plane, so the motion does too: that keeps the problem
/// well-conditioned (out of the plane the sagging top edge buckles and 1e-12 m grows to
/// centimetres within the second).
Scene hanging_cloth(int n);

/// Upper bound on the highest angular frequency of the cloth's springs about rest (Gershgorin on
/// M^-1 K: max over nodes of (2 sum ks) / m).
double omega_bound(const Scene& scene);

/// The suite as a sweep (comparisons/suites/sweep.h): for each cloth size, five untimed runs (the
/// reference, its confirmation, three conditioning probes), then one case per engine and step (a
/// timed run and a rerun for reproducibility; the wall seconds travel in the case's result).
Sweep tradeoff_sweep(const SuiteContext& ctx);
SuiteResult run_tradeoff_suite(const SuiteContext& ctx);

}  // namespace tecido::suites
