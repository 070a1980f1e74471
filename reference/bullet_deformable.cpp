// The deformable-world twin. The only unit that includes Bullet's deformable headers; built in
// the tecido_bullet library with the float64 Bullet (BT_USE_DOUBLE_PRECISION, private to it).
//
// Set-up facts this file relies on (Bullet 3.24 as packaged by Debian 12; measured, see
// docs/dependencies.md):
//  - btDeformableMultiBodyConstraintSolver needs setDeformableSolver() or stepping segfaults;
//  - btSoftBody must be built with the 4-argument constructor (the 1-argument one has no
//    material and appendNode/appendLink crash);
//  - the first step (m_bUpdateRtCst) resets every link's rest length to the current distance, and
//    so would any later setMass/setTotalMass: we run that update ourselves at construction and
//    then write the scene's rest lengths;
//  - addForce merges forces of one type: a second btDeformableMassSpringForce is ignored, so one
//    force carries every link (elastic k for ordinary links, bending k for m_bbending links);
//  - explicit mode is the default and is restated every step by the world (setImplicit);
//  - the world clamps each velocity component to m_maxDisplacement / dt (1000 m / dt).
#include "reference/bullet_deformable.h"
#include "reference/bullet_common.h"

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletSoftBody/btDeformableBodySolver.h>
#include <BulletSoftBody/btDeformableGravityForce.h>
#include <BulletSoftBody/btDeformableMassSpringForce.h>
#include <BulletSoftBody/btDeformableMultiBodyConstraintSolver.h>
#include <BulletSoftBody/btDeformableMultiBodyDynamicsWorld.h>
#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

static_assert(sizeof(btScalar) == sizeof(double), "the Bullet adapters need the float64 Bullet build");

namespace tecido::reference {

namespace {

// btDeformableBodySolver keeps its iteration caps protected (m_maxNewtonIterations, and the
// Krylov solvers m_cg, used with projection, and m_cr, without); this subclass only sets them.
class TunableDeformableBodySolver : public btDeformableBodySolver {
 public:
  void set_iterations(int newton, int krylov) {
    if (newton > 0) m_maxNewtonIterations = newton;
    if (krylov > 0) {
      m_cg.m_maxIterations = krylov;
      m_cr.m_maxIterations = krylov;
    }
  }
};

}  // namespace

struct DeformableTwin::Impl {
  Scene scene;
  DeformableTwinOptions options;
  std::vector<std::string> not_modelled;

  btSoftBodyRigidBodyCollisionConfiguration collision_config;
  std::unique_ptr<btCollisionDispatcher> dispatcher;
  std::unique_ptr<btDbvtBroadphase> broadphase;
  std::unique_ptr<TunableDeformableBodySolver> body_solver;
  std::unique_ptr<btDeformableMultiBodyConstraintSolver> constraint_solver;
  std::unique_ptr<btDeformableMultiBodyDynamicsWorld> world;
  btSoftBody* body = nullptr;  // owned; deleted after removal from the world
  std::unique_ptr<btDeformableMassSpringForce> spring_force;
  std::unique_ptr<btDeformableGravityForce> gravity_force;
  PlaneBoxes planes;

  long long steps = 0;
  bool unstable = false;

  Impl(const Scene& s, const DeformableTwinOptions& o);
  ~Impl();
  void build_world();
  void build_body();
  void build_springs();
  void report_unmodelled();
};

DeformableTwin::Impl::Impl(const Scene& s, const DeformableTwinOptions& o) : scene(s), options(o) {
  if (!(scene.dt > 0.0)) throw std::invalid_argument("DeformableTwin: scene.dt must be positive");
  if (options.newton_iterations < 0 || options.krylov_iterations < 0)
    throw std::invalid_argument("DeformableTwin: iteration counts must be >= 0 (0 = Bullet's default)");
  build_world();
  build_body();
  if (spring_force) world->addForce(body, spring_force.get());
  if (scene.forces.gravity) {
    gravity_force = std::make_unique<btDeformableGravityForce>(to_bt(*scene.forces.gravity));
    world->addForce(body, gravity_force.get());
  }
  planes.add(*world, scene, options.plane_thickness, options.collision_margin, not_modelled);
  report_unmodelled();
}

void DeformableTwin::Impl::build_world() {
  dispatcher = std::make_unique<btCollisionDispatcher>(&collision_config);
  broadphase = std::make_unique<btDbvtBroadphase>();
  body_solver = std::make_unique<TunableDeformableBodySolver>();
  body_solver->set_iterations(options.newton_iterations, options.krylov_iterations);
  constraint_solver = std::make_unique<btDeformableMultiBodyConstraintSolver>();
  constraint_solver->setDeformableSolver(body_solver.get());  // without it: segfault on step
  world = std::make_unique<btDeformableMultiBodyDynamicsWorld>(dispatcher.get(), broadphase.get(),
                                                               constraint_solver.get(), &collision_config,
                                                               body_solver.get());
  const Vec3 g = scene.forces.gravity.value_or(Vec3::Zero());
  world->setGravity(to_bt(g));                 // rigid bodies only (our planes are static)
  world->getWorldInfo().m_gravity = to_bt(g);  // defaults to (0,-10,0); unused by this world's nodes
  world->setImplicit(options.implicit);        // explicit = symplectic Euler
  world->setUseProjection(options.implicit);   // implicit mode freezes without projection
  world->setLineSearch(false);
}

void DeformableTwin::Impl::build_body() {
  const auto& p = scene.particles;
  body = new btSoftBody(&world->getWorldInfo(), 0, nullptr, nullptr);
  body->getCollisionShape()->setMargin(options.collision_margin);
  append_nodes(*body, p);
  // Bullet clamps every node's speed, in explicit mode, to the diagonal of the body's bounding box
  // divided by dt (btDeformableBodySolver::predictDeformableMotion): a lone particle thrown at
  // 3.6 m/s with dt = 1/240 s and a 1 mm margin is slowed to 0.83 m/s in the first step. A pinned
  // anchor node far away (appended after the scene's nodes, never reported) widens the box so the
  // clamp sits above kSpeedHeadroom. It has no links and no mass, so no force reaches it.
  constexpr double kSpeedHeadroom = 1e6;  // [m/s]
  Vec3 centre = Vec3::Zero();
  for (const Vec3& x : p.x) centre += x;
  if (!p.x.empty()) centre /= static_cast<double>(p.x.size());
  body->appendNode(to_bt(centre + Vec3::Ones().normalized() * (kSpeedHeadroom * scene.dt)), 0.0);
  build_springs();
  // Node-versus-rigid contacts through Bullet's signed-distance field (nodes only: core tests
  // particles, not triangles, against planes). In 3.24 SDF_RD alone detects nothing: the node
  // branch also needs SDF_RDN. Without planes no collision work at all.
  body->m_cfg.collisions = scene.planes.empty() ? 0 : (btSoftBody::fCollision::SDF_RD | btSoftBody::fCollision::SDF_RDN);
  body->m_cfg.kCHR = 1;
  body->m_cfg.kKHR = 1;
  body->m_cfg.kDF = 1;  // Bullet multiplies by the collider's friction (= the plane's)
  body->m_cfg.drag = 0;
  body->setActivationState(DISABLE_DEACTIVATION);  // a sleeping body stops moving
  world->addSoftBody(body);
  std::vector<double> rest;
  for (const Spring& sp : scene.forces.springs) rest.push_back(sp.rest_length);
  freeze_rest_lengths(*body, rest);
}

void DeformableTwin::Impl::build_springs() {
  const auto& springs = scene.forces.springs;
  if (springs.empty()) return;
  const SpringFamilies f = spring_families(scene);
  not_modelled.insert(not_modelled.end(), f.notes.begin(), f.notes.end());
  if (f.damping != 0.0) {
    not_modelled.push_back(
        "spring damping: Bullet solves the damping force backward-Euler in velocity (conjugate gradient), even in "
        "explicit mode; core applies c ((vj - vi).u) u explicitly");
  }
  for (std::size_t s = 0; s < springs.size(); ++s) {
    body->appendLink(springs[s].i, springs[s].j, nullptr, false);
    // m_bbending is a signed 1-bit field: "true" is stored as -1.
    body->m_links[body->m_links.size() - 1].m_bbending = f.bending[s] ? -1 : 0;
  }
  spring_force = std::make_unique<btDeformableMassSpringForce>(f.k_elastic, f.damping, true, f.k_bending);
}

void DeformableTwin::Impl::report_unmodelled() {
  if (options.implicit) {
    not_modelled.push_back(
        "integrator: implicit mode, Bullet's Newton iterations on a linearised backward-Euler step (projection on), "
        "not symplectic Euler: it damps the motion");
  } else if (scene.integrator != IntegratorKind::Symplectic) {
    not_modelled.push_back(std::string("integrator ") + integrator_name(scene.integrator) +
                           ": Bullet's explicit deformable step is symplectic Euler only");
  }
  if (scene.forces.air_drag && *scene.forces.air_drag != 0.0) {
    not_modelled.push_back(
        "air_drag: Bullet's deformable drag (m_cfg.drag) scales every velocity by (1 - drag) each step, one value per "
        "body, not a force -c v per particle; air drag is not applied");
  }
  if (scene.forces.wind) {
    not_modelled.push_back(
        "wind: Bullet has no constant force per node (its wind is an aerodynamic velocity acting through faces); wind is "
        "not applied");
  }
  if (!scene.planes.empty()) {
    not_modelled.push_back("bounded planes: modelled as static boxes (thickness " + note_number(options.plane_thickness) +
                           " m) behind each plane; Bullet holds resting nodes about the collision margin (" +
                           note_number(options.collision_margin) +
                           " m) off the face, detects contacts on the predicted position x + h v (no time of "
                           "contact, no bisection) through its sparse signed-distance field");
    not_modelled.push_back(
        "per-particle elasticity: Bullet's deformable-rigid contact is inelastic (no restitution), so the elastic "
        "branch of eq. 9 is not reproduced");
    not_modelled.push_back(
        "plane friction: Bullet applies Coulomb friction (coefficient = plane friction) inside its contact solve; core "
        "scales a large tangential velocity by (1 - mu) per step and zeroes a small one");
  }
}

DeformableTwin::Impl::~Impl() {
  // Bullet owns none of these; tear down in reverse order of dependence.
  if (world) {
    planes.remove(*world);
    if (body) {
      world->removeSoftBodyForce(body);  // removeSoftBody leaves the forces' pointers to it
      world->removeSoftBody(body);
    }
  }
  delete body;
  world.reset();  // before the solvers, dispatcher and broadphase it points to
  constraint_solver.reset();
  body_solver.reset();  // its objective lists the forces: drop it before them
  spring_force.reset();
  gravity_force.reset();
}

DeformableTwin::DeformableTwin(const Scene& scene, const DeformableTwinOptions& options)
    : impl_(std::make_unique<Impl>(scene, options)) {}
DeformableTwin::~DeformableTwin() = default;
DeformableTwin::DeformableTwin(DeformableTwin&&) noexcept = default;
DeformableTwin& DeformableTwin::operator=(DeformableTwin&&) noexcept = default;

bool DeformableTwin::step() {
  Impl& m = *impl_;
  if (m.unstable) return false;
  const double h = m.scene.dt;
  const int substeps = m.world->stepSimulation(h, 1, h);
  if (substeps != 1) throw std::logic_error("DeformableTwin: Bullet took " + std::to_string(substeps) + " internal steps");
  ++m.steps;
  m.unstable = !nodes_finite(*m.body, m.scene.particles.size());  // not the anchor
  return !m.unstable;
}

std::vector<Vec3> DeformableTwin::positions() const { return node_positions(*impl_->body, impl_->scene.particles.size()); }
std::vector<Vec3> DeformableTwin::velocities() const { return node_velocities(*impl_->body, impl_->scene.particles.size()); }
std::vector<std::string> DeformableTwin::not_modelled() const { return impl_->not_modelled; }
double DeformableTwin::time() const { return static_cast<double>(impl_->steps) * impl_->scene.dt; }
long long DeformableTwin::steps_done() const { return impl_->steps; }
double DeformableTwin::plane_contact_offset() const { return impl_->planes.contact_offset(); }

GuardedRun run_deformable_twin(const Scene& scene, double h, double seconds, const DeformableTwinOptions& options,
                               double stray_limit) {
  if (!(h > 0.0) || !(seconds >= 0.0)) throw std::invalid_argument("run_deformable_twin: h must be positive, seconds >= 0");
  Scene s = scene;
  s.dt = h;
  s.integrator = IntegratorKind::Symplectic;  // the scene's own integrator is not this run's
  DeformableTwin twin(s, options);
  return run_guarded(twin, scene.particles.x, fixed_time_steps(seconds, h), stray_limit);
}

}  // namespace tecido::reference
