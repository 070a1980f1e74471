#pragma once
/// Bullet 3.24's deformable world (btDeformableMultiBodyDynamicsWorld, Han et al., the
/// "deformable" solver that ships with Bullet/PyBullet) as a like-for-like twin of core's
/// symplectic Euler: the same nodes in core's numbering, masses, pins, Hooke springs, gravity and
/// time step, stepped in explicit mode. Only core types cross this header; Bullet stays inside
/// bullet_deformable.cpp (double-precision build, BT_USE_DOUBLE_PRECISION private to that unit).
///
/// Explicit mode is symplectic Euler: v += h (f_spring(x_n) + m g) / m, then x += h v. Spring
/// force is plain Hooke k (|d| - l) d/|d| (btDeformableMassSpringForce). Anything the scene asks
/// for that this engine cannot reproduce is listed by not_modelled(), never silently dropped.
#include "core/geometry/types.h"
#include "core/scene/scene.h"
#include "reference/guarded_run.h"

#include <memory>
#include <string>
#include <vector>

namespace tecido::reference {

/// Settings that have no counterpart in a core Scene (how bounded planes are built in Bullet).
struct DeformableTwinOptions {
  /// Collision margin of the cloth [m]: Bullet keeps a node about this far from a collider.
  /// (Bullet's default, 0.25 m, is sized for metre-scale demo objects.)
  double collision_margin = 1e-3;
  /// Thickness [m] of the static box that stands in for each bounded plane (a btStaticPlaneShape
  /// cannot be bounded). The box lies behind the plane, on the side away from every free particle,
  /// so its front face is the plane itself; it must be thicker than a node moves in one step or
  /// nodes tunnel. When free particles start on both sides the box is centred on the plane and
  /// not_modelled() says so.
  double plane_thickness = 0.1;
  /// Bullet's implicit mode instead of the explicit twin: btDeformableBodySolver's Newton loop on
  /// a linearised backward-Euler step (world.setImplicit(true) with setUseProjection(true); without
  /// projection the cloth silently freezes). Not core's symplectic Euler: not_modelled() says so.
  bool implicit = false;
  /// The deformable world's solver iterations. newton_iterations: Newton steps per time step in
  /// implicit mode (Bullet stops earlier when the residual norm falls below 1e-4); 0 = Bullet's
  /// default, 5. krylov_iterations: the cap on conjugate-gradient iterations per linear solve (in
  /// explicit mode the conjugate-residual solve of M dv = h f, which its mass preconditioner
  /// settles in one iteration when nothing is damped, so this knob does not change the result);
  /// 0 = Bullet's default, 300.
  int newton_iterations = 0;
  int krylov_iterations = 0;
};

/// The deformable-world twin of one Scene. Its stepping calls (step, positions, velocities,
/// not_modelled, time, steps_done) are those of every dynamics engine; reference/ depends on core
/// only, so they are plain members, and comparisons/engines/bullet_dynamics.h puts the engine
/// behind the suites' DynamicsEngine interface. Not copyable (Bullet keeps pointers into it); movable.
class DeformableTwin {
 public:
  /// Builds the world: a btSoftBody with node i = scene particle i (position, velocity, and the
  /// scene's inverse mass copied bit for bit; pinned = inverse mass 0), link s = scene spring s
  /// (btSoftBody::appendLink in spring order, rest length set to the scene's, after Bullet's
  /// update of runtime constants so it is not reset to the current distance), one
  /// btDeformableMassSpringForce and one btDeformableGravityForce (when the scene has gravity),
  /// planes as static boxes (DeformableTwinOptions) met by node contacts (SDF_RD | SDF_RDN),
  /// explicit mode, one internal step of scene.dt per step(). One extra pinned, massless node
  /// far away (after the scene's nodes, never reported) lifts Bullet's explicit-mode speed clamp
  /// |v| <= (bounding-box diagonal) / dt, which would otherwise slow small, fast bodies.
  /// Bullet's mass-spring force has one elastic k and one "bending" k: which springs are which
  /// comes from the scene's cloth spec (type B elastic, type A bending; spring_families in
  /// bullet_common.h), or from the springs' own stiffnesses in a scene without a cloth; a spring
  /// that fits neither family is reported by not_modelled().
  explicit DeformableTwin(const Scene& scene, const DeformableTwinOptions& options = {});
  ~DeformableTwin();
  DeformableTwin(DeformableTwin&&) noexcept;
  DeformableTwin& operator=(DeformableTwin&&) noexcept;
  DeformableTwin(const DeformableTwin&) = delete;
  DeformableTwin& operator=(const DeformableTwin&) = delete;

  /// Advances one step of scene.dt (stepSimulation(dt, 1, dt): exactly one internal step).
  /// Returns false when a position or velocity became NaN or infinite; later calls do nothing
  /// and return false (as core's Simulation::step).
  bool step();
  /// Node positions in core's numbering (node i = scene particle i) [m].
  std::vector<Vec3> positions() const;
  /// Node velocities in core's numbering [m/s].
  std::vector<Vec3> velocities() const;
  /// Scene features this engine does not reproduce, one line each: "<feature>: <why>".
  /// Empty when the twin is exact (up to round-off) for this scene.
  std::vector<std::string> not_modelled() const;
  /// Simulated time [s] = steps_done() * scene.dt.
  double time() const;
  long long steps_done() const;
  /// Distance [m] from a plane at which Bullet holds a resting node (the collision margin);
  /// compare rest heights and contact times against core with this offset in mind.
  double plane_contact_offset() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Runs `scene` (its own dt and integrator ignored) with a DeformableTwin from its initial state
/// for round(seconds / h) steps of h [s] through the guarded runner (guarded_run.h: a non-finite
/// state, or a node more than `stray_limit` [m] from its start, ends the run as failed).
GuardedRun run_deformable_twin(const Scene& scene, double h, double seconds, const DeformableTwinOptions& options = {},
                               double stray_limit = 1e3);

}  // namespace tecido::reference
