#pragma once
/// Bullet 3.24's classic soft body (btSoftBody in a btSoftRigidDynamicsWorld, Nathanael Presson's
/// position-based cloth, the one games and most Bullet users run) built from a core Scene in
/// core's numbering. Only core types cross this header; Bullet stays inside bullet_softbody.cpp
/// (double-precision build, BT_USE_DOUBLE_PRECISION private to that unit).
///
/// Method (btSoftBody::predictMotion / solveConstraints): v += h g; x += h v; then piterations
/// sweeps project every link towards its rest length, scaled by the material's kLST in [0, 1];
/// finally v = (x - x_old)/h * (1 - kDP). The links are constraints, not Hooke springs: kLST has
/// no unit and its effect depends on dt and piterations, so it has to be calibrated against core's
/// ks (calibrate_klst_for_sag below) before any comparison of shapes.
#include "core/geometry/types.h"
#include "core/scene/scene.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tecido::reference {

/// Settings of the classic soft body that have no counterpart in a core Scene.
struct ClassicSoftBodyOptions {
  /// Linear stiffness coefficient kLST in (0, 1] of the stiffest springs (Bullet's default 1).
  /// Springs with a smaller ks get kLST * ks / ks_max (a linear heuristic; not_modelled() says so).
  double klst = 1.0;
  int piterations = 10;  ///< position-solver sweeps per step, m_cfg.piterations (Bullet's default 1)
  double kdp = 0.0;      ///< velocity damping m_cfg.kDP in [0, 1]: v *= (1 - kDP) each step
  /// Self-collision by Bullet's cluster collider: on when this is set or when the scene's
  /// self_collision key asks for a response other than "none"; off otherwise.
  /// In 3.24 the flags CL_SS | CL_SELF never reach the self-collision branch, so the adapter keeps
  /// CL_SS, generates clusters, and after each step runs btSoftColliders::CollideCL_SS on the body
  /// against itself; the contact joints it creates are solved during the next step.
  bool self_collision = false;
  /// Clusters for self-collision: 0 = one per triangle (needs the scene's triangles; memory and
  /// set-up time grow as triangles^2), k > 0 = Bullet's k-means clustering into k clusters.
  int self_collision_clusters = 0;
  double collision_margin = 1e-3;  ///< [m], see DeformableTwinOptions
  double plane_thickness = 0.1;    ///< [m], see DeformableTwinOptions
};

/// The classic soft body of one Scene. Not copyable; movable.
class ClassicSoftBody {
 public:
  /// Builds the world: node i = scene particle i (position, velocity, inverse mass; pinned = 0),
  /// link s = scene spring s with the scene's rest length (written after Bullet's one-time reset of
  /// rest lengths), faces = scene.triangles in order, gravity in both the world and its
  /// btSoftBodyWorldInfo (the latter moves the nodes and defaults to (0,-10,0)), planes as static
  /// boxes, stepSimulation(dt, 1, dt) per step.
  explicit ClassicSoftBody(const Scene& scene, const ClassicSoftBodyOptions& options = {});
  ~ClassicSoftBody();
  ClassicSoftBody(ClassicSoftBody&&) noexcept;
  ClassicSoftBody& operator=(ClassicSoftBody&&) noexcept;
  ClassicSoftBody(const ClassicSoftBody&) = delete;
  ClassicSoftBody& operator=(const ClassicSoftBody&) = delete;

  /// Advances one step of scene.dt. Returns false when a position or velocity became NaN or
  /// infinite; later calls do nothing and return false.
  bool step();
  /// Node positions in core's numbering [m].
  std::vector<Vec3> positions() const;
  /// Node velocities in core's numbering [m/s].
  std::vector<Vec3> velocities() const;
  /// Scene features this engine does not reproduce (or reproduces differently), one line each:
  /// "<feature>: <why>".
  std::vector<std::string> not_modelled() const;
  double time() const;
  long long steps_done() const;
  const ClassicSoftBodyOptions& options() const;
  /// Distance [m] from a plane at which Bullet holds a resting node (see DeformableTwin).
  double plane_contact_offset() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

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
  double relative_tolerance = 1e-3;  ///< bisection stops when |sag error| <= this * |core sag|
  int max_bisections = 40;
  double klst_min = 1e-4;  ///< lower end of the kLST bracket (upper end is 1)
  /// When > 0, a first estimate of kLST: the search starts there with a safeguarded secant on
  /// log sag against log kLST (the sag of a stretch-dominated cloth is close to a power law in
  /// kLST), typically 2-4 settles instead of about a dozen, and never probes kLST = 1 unless the
  /// secant goes there (sag_at_klst_1 is then NaN). 0 = bisection on [klst_min, 1] as described below.
  double klst_guess = 0.0;
};

/// What calibrate_klst_for_sag found, for the suite's report.
struct SagCalibration {
  double klst = 1.0;            ///< the calibrated kLST
  double core_sag = 0.0;        ///< core's settled mean sag [m]
  double bullet_sag = 0.0;      ///< Bullet's settled mean sag with klst [m]
  double sag_error = 0.0;       ///< bullet_sag - core_sag [m]
  double relative_error = 0.0;  ///< |sag_error| / |core_sag|
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

/// Calibrates the classic soft body's kLST to core's Hooke stiffness by matching the static sag
/// (mean_sag) of the scene's cloth under gravity. Method: core (symplectic Euler, with the scene's
/// air drag or options.core_air_drag) runs from the scene's initial state until every particle is
/// slower than rest_speed; then Bullet (ClassicSoftBody with options.piterations and kdp, same dt)
/// is settled the same way for trial kLST values, bisected in log kLST on [klst_min, 1] (the sag
/// falls as kLST grows), until the sag matches within relative_tolerance. Meaningful when the sag
/// is dominated by stretch (e.g. a cloth hanging from its top row); a sag set by geometry alone
/// (a slack cloth draped from two corners) hardly depends on kLST. Returns kLST (1 or klst_min
/// when core's sag is outside what Bullet reaches: bracketed = false) and fills *result.
/// Throws std::invalid_argument when the scene has no gravity or no free particle, and
/// std::runtime_error when either engine goes unstable (NaN/Inf) while settling.
/// Measured (6x6 curtain 0.3 m, 0.1 kg, ks = 100 N/m, dt = 1 ms, piterations 10, kDP 0.05):
/// kLST = 0.0045, mean sag matched to 0.02 %, settled shapes 0.23 mm RMS apart for a 1.95 mm sag;
/// kLST scales with ks (ks = 30: 0.00135) but not with anything else: 4 piterations give 0.011,
/// an 11x11 grid 0.019. Recalibrate for every dt, piterations and mesh.
double calibrate_klst_for_sag(const Scene& scene, const SagCalibrationOptions& options = {},
                              SagCalibration* result = nullptr);

/// Runs `scene` (its own dt ignored) with a ClassicSoftBody built with `options` from its initial
/// state for round(seconds / h) steps of h [s] and returns the node positions in core's numbering
/// [m], or nothing when the run became unstable: a non-finite state, or a node more than
/// `stray_limit` [m] from its start (checked every 64 steps and at the end; the position solver
/// keeps most bad runs bounded, so this rarely fires: a bounded but wrong run is judged by its error).
std::optional<std::vector<Vec3>> run_classic_soft_body(const Scene& scene, double h, double seconds,
                                                       const ClassicSoftBodyOptions& options = {},
                                                       double stray_limit = 1e3);

}  // namespace tecido::reference
