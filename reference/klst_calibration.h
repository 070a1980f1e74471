#pragma once
/// Calibrating the classic soft body's link stiffness kLST (bullet_softbody.h) against core's Hooke
/// springs by matching the static sag of a hanging cloth, and the settling runs it is made of.
///
/// Why it is needed, and what it cannot do: the classic body's links are position constraints,
/// not springs. Each of its piterations sweeps moves a link's two nodes by the fraction kLST of the
/// link's violation, split by the ratio of their inverse masses; gravity enters as an acceleration.
/// So its settled shape does not depend on the masses at all (doubling every mass leaves every
/// ratio, and every bit of the result, unchanged), while a Hooke cloth's sag is proportional to
/// its load. A kLST matched at one load is therefore wrong at every other load, as it is for
/// another dt, number of sweeps or mesh (docs/dependencies.md). Only core and Bullet-free types
/// here; the calibration drives ClassicSoftBody through its Bullet-free interface.
#include "core/scene/scene.h"

#include <vector>

namespace tecido::reference {

/// Mean displacement along gravity [m] of the scene's free (unpinned) particles, from their
/// initial positions in `scene` to `x` (positive = moved down). The sag the calibration matches.
/// Throws std::invalid_argument when the scene has no gravity, or x has the wrong size.
double mean_sag(const Scene& scene, const std::vector<Vec3>& x);

/// How calibrate_klst_for_sag settles both engines and when it stops.
struct SagCalibrationOptions {
  int piterations = 10;  ///< classic position sweeps; the kLST found is valid for these and scene.dt only
  double kdp = 0.05;     ///< classic damping used to settle (kDP)
  /// Linear drag [kg/s] core settles with when the scene has none; 0 = 10 /s times the mean mass
  /// of the free particles. The settled shape does not depend on it.
  double core_air_drag = 0.0;
  double rest_speed = 1e-6;          ///< settled when every node is slower than this [m/s]
  double max_time = 60.0;            ///< simulated time after which a settle gives up [s]
  double relative_tolerance = 1e-3;  ///< the search stops when |sag error| <= this * |core sag|
  int max_bisections = 40;           ///< at most this many search steps after the first trials
  double klst_min = 1e-4;            ///< lower end of the kLST bracket (upper end is 1)
  /// When > 0, a first estimate of kLST (klst_scaling_guess): the search starts there with a
  /// safeguarded secant on log sag against log kLST (the sag of a stretch-dominated cloth is close
  /// to a power law in kLST), typically 2-4 settles instead of about a dozen, and never probes
  /// kLST = 1 unless the secant goes there (sag_at_klst_1 is then NaN). 0 = bisection in log kLST
  /// on [klst_min, 1].
  double klst_guess = 0.0;
};

/// What calibrate_klst_for_sag found, for a suite's report.
struct SagCalibration {
  double klst = 1.0;            ///< the calibrated kLST
  double core_sag = 0.0;        ///< core's settled mean sag [m]
  double bullet_sag = 0.0;      ///< Bullet's settled mean sag with klst [m]
  double sag_error = 0.0;       ///< bullet_sag - core_sag [m]
  double relative_error = 0.0;  ///< |sag_error| / |core_sag|: the calibrator's own stopping rule
  double sag_at_klst_1 = 0.0;   ///< Bullet's sag with kLST = 1: how far the uncalibrated default is (NaN if not run)
  /// RMS over all nodes of |x_core - x_bullet| between the two settled shapes at klst [m]: how
  /// well the shape, not only the mean sag, matches.
  double shape_rms = 0.0;
  double shape_max = 0.0;       ///< largest node distance between the two settled shapes [m]
  int evaluations = 0;          ///< Bullet settles run
  bool bracketed = false;       ///< core's sag lies between Bullet's sags at klst_min and 1 (or was matched)
  bool core_settled = false;    ///< core reached rest_speed within max_time
  bool bullet_settled = false;  ///< the final Bullet run reached rest_speed within max_time
  int piterations = 0;          ///< copied from the options: kLST is meaningless without them
  double kdp = 0.0;
  double dt = 0.0;
};

/// A run to rest.
struct Settled {
  std::vector<Vec3> x;   ///< final positions, core's numbering [m]
  bool settled = false;  ///< every node got slower than the rest speed before the time ran out
};

/// Core's shape at rest: symplectic Euler (the equilibrium does not depend on the integrator)
/// with the scene's air drag, or o.core_air_drag when it has none (0: 10 /s times the mean mass of
/// the free particles), stepped until every node is slower than o.rest_speed or o.max_time has
/// been simulated. Throws std::runtime_error when a step reports a non-finite state.
Settled settle_core(const Scene& scene, const SagCalibrationOptions& o);
/// The classic soft body's shape at rest with `klst`, o.piterations and o.kdp at scene.dt, settled
/// as in settle_core.
Settled settle_classic(const Scene& scene, double klst, const SagCalibrationOptions& o);

/// Calibrates the classic soft body's kLST to core's Hooke stiffness by matching the static sag
/// (mean_sag) of the scene's cloth under gravity. Method: core settles (settle_core); then Bullet
/// is settled the same way (settle_classic) for trial kLST values, searched in log kLST on
/// [klst_min, 1] (the sag falls as kLST grows; bisection, or the secant of
/// SagCalibrationOptions::klst_guess), until the sag matches within relative_tolerance.
/// Meaningful when the sag is dominated by stretch (a cloth hanging from its top row); a sag set
/// by geometry alone (a slack cloth draped from two corners) hardly depends on kLST. Returns kLST
/// (1 or klst_min when core's sag is outside what Bullet reaches: bracketed = false) and fills
/// *result. Throws std::invalid_argument when the scene has no gravity or no free particle, and
/// std::runtime_error when either engine goes unstable (NaN/Inf) while settling. The result holds
/// at the scene's load, dt, piterations and mesh only (see the top of this file).
double calibrate_klst_for_sag(const Scene& scene, const SagCalibrationOptions& options = {},
                              SagCalibration* result = nullptr);

/// A first estimate of kLST for the secant start (SagCalibrationOptions::klst_guess). One sweep of
/// Bullet's link projection removes the fraction kLST of a link's stretch; a Hooke spring of
/// stiffness k between nodes of inverse masses w_i, w_j removes about h^2 k (w_i + w_j) of it in
/// one symplectic step. Equating the two over `piterations` sweeps, -ln(1 - kLST) piterations =
/// c h^2 k_max (2 w), with w the median free inverse mass and c = 0.8 fitted on the tradeoff
/// suite's 16^2 curtain (calibrated kLST 0.20, 0.053, 0.0136 at 1, 4, 16 sweeps; halving h follows
/// the h^2 law within 3 %). Clamped to [1e-4, 1]; 1 for a scene without free mass or springs.
double klst_scaling_guess(const Scene& scene, double h, int piterations);

}  // namespace tecido::reference
