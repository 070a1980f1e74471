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
/// ks (calibrate_klst_for_sag, klst_calibration.h) before any comparison of shapes.
#include "core/geometry/types.h"
#include "core/scene/scene.h"
#include "reference/guarded_run.h"

#include <memory>
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

/// The classic soft body of one Scene, with the stepping calls of every dynamics engine as plain
/// members (see DeformableTwin). Not copyable; movable.
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

/// Runs `scene` (its own dt and integrator ignored) with a ClassicSoftBody built with `options`
/// from its initial state for round(seconds / h) steps of h [s] through the guarded runner
/// (guarded_run.h). The position solver keeps most bad runs bounded, so the stray test rarely
/// fires: a bounded but wrong run is judged by its error.
GuardedRun run_classic_soft_body(const Scene& scene, double h, double seconds, const ClassicSoftBodyOptions& options = {},
                                 double stray_limit = 1e3);

}  // namespace tecido::reference
