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
#include "reference/guarded_run.h"
#include "reference/plane_box.h"

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btDeformableBodySolver.h>
#include <BulletSoftBody/btDeformableGravityForce.h>
#include <BulletSoftBody/btDeformableMassSpringForce.h>
#include <BulletSoftBody/btDeformableMultiBodyConstraintSolver.h>
#include <BulletSoftBody/btDeformableMultiBodyDynamicsWorld.h>
#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <LinearMath/btDefaultMotionState.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

static_assert(sizeof(btScalar) == sizeof(double), "the Bullet adapters need the float64 Bullet build");

namespace tecido::reference {

namespace {

btVector3 to_bt(const Vec3& v) { return btVector3(v.x(), v.y(), v.z()); }
Vec3 from_bt(const btVector3& v) { return Vec3(v.x(), v.y(), v.z()); }

std::string num(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

// Distinct values in first-appearance order with their counts.
std::vector<std::pair<double, std::size_t>> histogram(const std::vector<double>& values) {
  std::vector<std::pair<double, std::size_t>> h;
  for (double v : values) {
    auto it = std::find_if(h.begin(), h.end(), [v](const auto& p) { return p.first == v; });
    if (it == h.end()) {
      h.emplace_back(v, 1);
    } else {
      ++it->second;
    }
  }
  // Most common first; ties keep first appearance (stable).
  std::stable_sort(h.begin(), h.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  return h;
}

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
  std::vector<std::unique_ptr<btBoxShape>> plane_shapes;
  std::vector<std::unique_ptr<btDefaultMotionState>> plane_states;
  std::vector<std::unique_ptr<btRigidBody>> plane_bodies;

  long long steps = 0;
  bool unstable = false;
  double contact_offset = 0.0;

  Impl(const Scene& s, const DeformableTwinOptions& o);
  ~Impl();
  void build_springs();
  void build_planes();
  void report_unmodelled();
};

DeformableTwin::Impl::Impl(const Scene& s, const DeformableTwinOptions& o) : scene(s), options(o) {
  if (!(scene.dt > 0.0)) throw std::invalid_argument("DeformableTwin: scene.dt must be positive");
  dispatcher = std::make_unique<btCollisionDispatcher>(&collision_config);
  broadphase = std::make_unique<btDbvtBroadphase>();
  if (options.newton_iterations < 0 || options.krylov_iterations < 0)
    throw std::invalid_argument("DeformableTwin: iteration counts must be >= 0 (0 = Bullet's default)");
  body_solver = std::make_unique<TunableDeformableBodySolver>();
  body_solver->set_iterations(options.newton_iterations, options.krylov_iterations);
  constraint_solver = std::make_unique<btDeformableMultiBodyConstraintSolver>();
  constraint_solver->setDeformableSolver(body_solver.get());  // without it: segfault on step
  world = std::make_unique<btDeformableMultiBodyDynamicsWorld>(dispatcher.get(), broadphase.get(),
                                                               constraint_solver.get(), &collision_config,
                                                               body_solver.get());
  const Vec3 g = scene.forces.gravity.value_or(Vec3::Zero());
  world->setGravity(to_bt(g));                  // rigid bodies only (our planes are static)
  world->getWorldInfo().m_gravity = to_bt(g);   // defaults to (0,-10,0); unused by this world's nodes
  world->setImplicit(options.implicit);         // explicit = symplectic Euler
  world->setUseProjection(options.implicit);    // implicit mode freezes without projection
  world->setLineSearch(false);

  const auto& p = scene.particles;
  body = new btSoftBody(&world->getWorldInfo(), 0, nullptr, nullptr);
  body->getCollisionShape()->setMargin(options.collision_margin);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double w = p.inv_mass[i];
    body->appendNode(to_bt(p.x[i]), w > 0.0 ? 1.0 / w : 0.0);
    btSoftBody::Node& n = body->m_nodes[body->m_nodes.size() - 1];
    n.m_im = w;  // exactly core's inverse mass (1/(1/m) may differ from 1/m in the last bit)
    n.m_v = to_bt(p.v[i]);
    n.m_vn = n.m_v;
  }
  // Bullet clamps every node's speed, in explicit mode, to the diagonal of the body's bounding box
  // divided by dt (btDeformableBodySolver::predictDeformableMotion): a lone particle thrown at
  // 3.6 m/s with dt = 1/240 s and a 1 mm margin is slowed to 0.83 m/s in the first step. A pinned
  // anchor node far away (appended after the scene's nodes, never reported) widens the box so the
  // clamp sits above kSpeedHeadroom. It has no links and no mass, so no force reaches it.
  {
    constexpr double kSpeedHeadroom = 1e6;  // [m/s]
    Vec3 centre = Vec3::Zero();
    for (const Vec3& x : p.x) centre += x;
    if (!p.x.empty()) centre /= static_cast<double>(p.x.size());
    body->appendNode(to_bt(centre + Vec3::Ones().normalized() * (kSpeedHeadroom * scene.dt)), 0.0);
  }
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

  // Run Bullet's "update runtime constants" now (it would run at the first step and set every
  // rest length to the current distance), then write the scene's rest lengths. Bullet's version
  // of this update also rebuilds the node tree bottom-up from the link graph (initializeFaceTree
  // -> rebuildNodeTree) when SDF_RD is set; that build never terminates when the links do not
  // connect every node (buildTreeBottomUp pairs only adjacent leaves), e.g. two free particles.
  // The node tree built incrementally by appendNode serves the same queries, so we skip it.
  body->updateConstants();
  body->m_bUpdateRtCst = false;
  for (std::size_t s_i = 0; s_i < scene.forces.springs.size(); ++s_i) {
    btSoftBody::Link& l = body->m_links[static_cast<int>(s_i)];
    l.m_rl = scene.forces.springs[s_i].rest_length;
    l.m_c1 = l.m_rl * l.m_rl;
  }

  if (spring_force) world->addForce(body, spring_force.get());
  if (scene.forces.gravity) {
    gravity_force = std::make_unique<btDeformableGravityForce>(to_bt(g));
    world->addForce(body, gravity_force.get());
  }
  build_planes();
  report_unmodelled();
}

void DeformableTwin::Impl::build_springs() {
  const auto& springs = scene.forces.springs;
  if (springs.empty()) return;
  std::vector<double> ks, ds;
  ks.reserve(springs.size());
  ds.reserve(springs.size());
  for (const Spring& s : springs) {
    ks.push_back(s.stiffness);
    ds.push_back(s.damping);
  }
  const auto kh = histogram(ks);
  const auto dh = histogram(ds);
  const double k_elastic = kh[0].first;
  const double k_bending = kh.size() > 1 ? kh[1].first : k_elastic;
  const double damping = dh[0].first;
  if (kh.size() > 2) {
    not_modelled.push_back("per-spring stiffness: the scene has " + std::to_string(kh.size()) +
                           " distinct spring stiffnesses; Bullet's btDeformableMassSpringForce has one elastic k (" +
                           num(k_elastic) + " N/m) and one bending k (" + num(k_bending) +
                           " N/m), so springs with other values use the nearer of the two");
  }
  if (dh.size() > 1) {
    not_modelled.push_back("per-spring damping: Bullet's mass-spring force has one damping coefficient for all links; " +
                           num(damping) + " N s/m is used for every spring");
  }
  if (damping != 0.0) {
    not_modelled.push_back(
        "spring damping: Bullet solves the damping force backward-Euler in velocity (conjugate gradient), even in "
        "explicit mode; core applies c ((vj - vi).u) u explicitly");
  }
  for (const Spring& s : springs) {
    const int n = static_cast<int>(scene.particles.size());
    if (s.i < 0 || s.j < 0 || s.i >= n || s.j >= n || s.i == s.j)
      throw std::invalid_argument("DeformableTwin: spring with an invalid end");
    body->appendLink(s.i, s.j, nullptr, false);
    const bool bending = kh.size() > 1 && std::abs(s.stiffness - k_bending) < std::abs(s.stiffness - k_elastic);
    // m_bbending is a signed 1-bit field: "true" is stored as -1.
    body->m_links[body->m_links.size() - 1].m_bbending = bending ? -1 : 0;
  }
  spring_force = std::make_unique<btDeformableMassSpringForce>(k_elastic, damping, true, k_bending);
}

void DeformableTwin::Impl::build_planes() {
  contact_offset = options.collision_margin;
  for (std::size_t k = 0; k < scene.planes.size(); ++k) {
    const PlaneBox box = plane_box(scene, k, options.plane_thickness, options.collision_margin);
    contact_offset = std::max(contact_offset, box.contact_offset);
    if (!box.note.empty()) not_modelled.push_back(box.note);
    auto shape = std::make_unique<btBoxShape>(to_bt(box.half_extents));
    shape->setMargin(box.shape_margin);
    const Vec3 &f = box.axes[0], &r = box.axes[1], &n = box.axes[2];
    btTransform tr;
    tr.setBasis(btMatrix3x3(f.x(), r.x(), n.x(), f.y(), r.y(), n.y(), f.z(), r.z(), n.z()));
    tr.setOrigin(to_bt(box.centre));
    auto state = std::make_unique<btDefaultMotionState>(tr);
    btRigidBody::btRigidBodyConstructionInfo info(0.0, state.get(), shape.get(), btVector3(0, 0, 0));
    info.m_friction = scene.planes[k].friction;
    info.m_restitution = 0.0;
    auto rb = std::make_unique<btRigidBody>(info);
    world->addRigidBody(rb.get());
    plane_shapes.push_back(std::move(shape));
    plane_states.push_back(std::move(state));
    plane_bodies.push_back(std::move(rb));
  }
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
    not_modelled.push_back("bounded planes: modelled as static boxes (thickness " + num(options.plane_thickness) +
                           " m) behind each plane; Bullet holds resting nodes about the collision margin (" +
                           num(options.collision_margin) +
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
    for (auto& rb : plane_bodies) world->removeRigidBody(rb.get());
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
  const int n_nodes = static_cast<int>(m.scene.particles.size());  // not the anchor
  for (int i = 0; i < n_nodes; ++i) {
    const btSoftBody::Node& n = m.body->m_nodes[i];
    if (!std::isfinite(n.m_x.x()) || !std::isfinite(n.m_x.y()) || !std::isfinite(n.m_x.z()) ||
        !std::isfinite(n.m_v.x()) || !std::isfinite(n.m_v.y()) || !std::isfinite(n.m_v.z())) {
      m.unstable = true;
      return false;
    }
  }
  return true;
}

std::vector<Vec3> DeformableTwin::positions() const {
  const std::size_t n = impl_->scene.particles.size();
  std::vector<Vec3> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) out.push_back(from_bt(impl_->body->m_nodes[static_cast<int>(i)].m_x));
  return out;
}

std::vector<Vec3> DeformableTwin::velocities() const {
  const std::size_t n = impl_->scene.particles.size();
  std::vector<Vec3> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) out.push_back(from_bt(impl_->body->m_nodes[static_cast<int>(i)].m_v));
  return out;
}

std::optional<std::vector<Vec3>> run_deformable_twin(const Scene& scene, double h, double seconds,
                                                     const DeformableTwinOptions& options, double stray_limit) {
  if (!(h > 0.0) || !(seconds >= 0.0)) throw std::invalid_argument("run_deformable_twin: h must be positive, seconds >= 0");
  Scene s = scene;
  s.dt = h;
  s.integrator = IntegratorKind::Symplectic;  // the scene's own integrator is not this run's
  DeformableTwin twin(s, options);
  return run_guarded(twin, scene.particles.x, std::llround(seconds / h), stray_limit);
}

std::vector<std::string> DeformableTwin::not_modelled() const { return impl_->not_modelled; }
double DeformableTwin::time() const { return static_cast<double>(impl_->steps) * impl_->scene.dt; }
long long DeformableTwin::steps_done() const { return impl_->steps; }
double DeformableTwin::plane_contact_offset() const { return impl_->contact_offset; }

}  // namespace tecido::reference
