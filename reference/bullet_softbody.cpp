// The classic Bullet soft body. The only unit that includes Bullet's classic soft-body headers;
// built in the tecido_bullet library with the float64 Bullet (BT_USE_DOUBLE_PRECISION private).
//
// Set-up facts this file relies on (Bullet 3.24, Debian 12; docs/dependencies.md):
//  - nodes are moved by btSoftBodyWorldInfo::m_gravity, which defaults to (0,-10,0) whatever the
//    world's gravity is: both are set;
//  - stepSimulation's default fixed step is 1/60 s: we call stepSimulation(dt, 1, dt);
//  - btSoftBodyHelpers::CreatePatch numbers faces and links its own way and calls rand(): nodes,
//    links and faces are built here in core's numbering instead;
//  - the first predictMotion (m_bUpdateRtCst) resets every rest length to the current distance:
//    we run that update at construction and then write the scene's rest lengths;
//  - kLST changed after the first step needs m_bUpdateRtCst (or updateLinkConstants) to matter;
//    the calibration (klst_calibration.cpp) builds a fresh body per trial instead;
//  - CL_SS | CL_SELF never runs in 3.24 (defaultCollisionHandler switches on the combined flag
//    value): self-collision keeps CL_SS, generates clusters and calls CollideCL_SS itself.
#include "reference/bullet_softbody.h"
#include "reference/bullet_common.h"

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftBodyInternals.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

static_assert(sizeof(btScalar) == sizeof(double), "the Bullet adapters need the float64 Bullet build");

namespace tecido::reference {

struct ClassicSoftBody::Impl {
  Scene scene;
  ClassicSoftBodyOptions options;
  std::vector<std::string> not_modelled;

  btSoftBodyRigidBodyCollisionConfiguration collision_config;
  std::unique_ptr<btCollisionDispatcher> dispatcher;
  std::unique_ptr<btDbvtBroadphase> broadphase;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver;
  std::unique_ptr<btSoftRigidDynamicsWorld> world;  // owns its default soft-body solver
  btSoftBody* body = nullptr;                       // owned; deleted after removal from the world
  PlaneBoxes planes;

  long long steps = 0;
  bool unstable = false;

  Impl(const Scene& s, const ClassicSoftBodyOptions& o);
  ~Impl();
  void validate();
  void build_world();
  void build_body();
  void build_links();
  void configure();
  void report_unmodelled();
  void report_forces();
};

ClassicSoftBody::Impl::Impl(const Scene& s, const ClassicSoftBodyOptions& o) : scene(s), options(o) {
  // Self-collision is switched on when the scene asks for a self-collision response (Bullet's
  // collider is a response; "none" in the scene means detection only), or by the options.
  if (s.self_collision && s.self_collision->response != SelfCollisionResponse::None) options.self_collision = true;
  validate();
  build_world();
  build_body();
  planes.add(*world, scene, options.plane_thickness, options.collision_margin, not_modelled);
  report_unmodelled();
}

void ClassicSoftBody::Impl::validate() {
  if (!(scene.dt > 0.0)) throw std::invalid_argument("ClassicSoftBody: scene.dt must be positive");
  if (!(options.klst > 0.0 && options.klst <= 1.0)) throw std::invalid_argument("ClassicSoftBody: klst must be in (0, 1]");
  if (options.piterations < 1) throw std::invalid_argument("ClassicSoftBody: piterations must be >= 1");
  if (!(options.kdp >= 0.0 && options.kdp <= 1.0)) throw std::invalid_argument("ClassicSoftBody: kdp must be in [0, 1]");
  const int np = static_cast<int>(scene.particles.size());
  for (const Spring& sp : scene.forces.springs)
    if (sp.i < 0 || sp.j < 0 || sp.i >= np || sp.j >= np || sp.i == sp.j)
      throw std::invalid_argument("ClassicSoftBody: spring with an invalid end");
  for (const auto& t : scene.triangles)
    if (t[0] < 0 || t[1] < 0 || t[2] < 0 || t[0] >= np || t[1] >= np || t[2] >= np)
      throw std::invalid_argument("ClassicSoftBody: triangle with an invalid particle index");
  if (options.self_collision && options.self_collision_clusters == 0 && scene.triangles.empty())
    throw std::invalid_argument("ClassicSoftBody: self-collision with one cluster per triangle needs triangles");
}

void ClassicSoftBody::Impl::build_world() {
  dispatcher = std::make_unique<btCollisionDispatcher>(&collision_config);
  broadphase = std::make_unique<btDbvtBroadphase>();
  solver = std::make_unique<btSequentialImpulseConstraintSolver>();
  world = std::make_unique<btSoftRigidDynamicsWorld>(dispatcher.get(), broadphase.get(), solver.get(), &collision_config);
  const Vec3 g = scene.forces.gravity.value_or(Vec3::Zero());
  world->setGravity(to_bt(g));
  btSoftBodyWorldInfo& info = world->getWorldInfo();
  info.m_gravity = to_bt(g);  // the one that moves soft-body nodes
  info.air_density = 0;
  info.water_density = 0;
  info.m_sparsesdf.Initialize();
}

void ClassicSoftBody::Impl::build_body() {
  body = new btSoftBody(&world->getWorldInfo(), 0, nullptr, nullptr);
  body->getCollisionShape()->setMargin(options.collision_margin);
  append_nodes(*body, scene.particles);
  build_links();
  for (const auto& t : scene.triangles) body->appendFace(t[0], t[1], t[2]);
  configure();
  world->addSoftBody(body);
  // (Bullet's own update would also rebuild the face tree bottom-up for VF_SS, which we never set;
  // that build does not terminate on a mesh whose faces are not edge-connected.)
  std::vector<double> rest;
  for (const Spring& sp : scene.forces.springs)
    if (sp.stiffness > 0.0) rest.push_back(sp.rest_length);  // the links build_links appended
  freeze_rest_lengths(*body, rest);
}

void ClassicSoftBody::Impl::configure() {
  body->m_cfg.piterations = options.piterations;
  body->m_cfg.kDP = options.kdp;
  body->m_cfg.kDG = 0;  // no aerodynamic drag or lift
  body->m_cfg.kLF = 0;
  body->m_cfg.kDF = 1;  // times the collider's friction (= the plane's)
  body->m_cfg.kCHR = 1;
  body->m_cfg.kKHR = 1;
  body->m_cfg.collisions = btSoftBody::fCollision::SDF_RS;
  if (options.self_collision) {
    body->m_cfg.collisions |= btSoftBody::fCollision::CL_SS;
    body->generateClusters(options.self_collision_clusters);
  }
  body->setActivationState(DISABLE_DEACTIVATION);
}

void ClassicSoftBody::Impl::build_links() {
  const auto& springs = scene.forces.springs;
  double k_max = 0.0;
  for (const Spring& s : springs) k_max = std::max(k_max, s.stiffness);
  // One material per distinct stiffness: kLST = options.klst * ks / ks_max.
  std::vector<std::pair<double, btSoftBody::Material*>> materials;
  for (const Spring& s : springs) {
    if (!(s.stiffness > 0.0)) continue;
    auto it = std::find_if(materials.begin(), materials.end(), [&](const auto& m) { return m.first == s.stiffness; });
    btSoftBody::Material* mat = nullptr;
    if (it == materials.end()) {
      mat = materials.empty() ? body->m_materials[0] : body->appendMaterial();
      mat->m_kLST = options.klst * s.stiffness / k_max;
      materials.emplace_back(s.stiffness, mat);
    } else {
      mat = it->second;
    }
    body->appendLink(s.i, s.j, mat, false);
  }
  if (materials.size() > 1) {
    not_modelled.push_back("per-spring stiffness: " + std::to_string(materials.size()) +
                           " distinct ks; each link's kLST is klst * ks / ks_max, a linear heuristic (position-based "
                           "stiffness is not proportional to ks)");
  }
}

void ClassicSoftBody::Impl::report_forces() {
  const auto& springs = scene.forces.springs;
  if (!springs.empty()) {
    not_modelled.insert(not_modelled.begin(),
                        "Hooke springs: links are position constraints projected towards their rest length (kLST = " +
                            note_number(options.klst) + ", piterations = " + std::to_string(options.piterations) +
                            "), not forces ks (|x| - l); compare shapes only with a calibrated kLST "
                            "(calibrate_klst_for_sag)");
  }
  std::size_t zero_k = 0;
  bool damped = false;
  for (const Spring& s : springs) {
    zero_k += s.stiffness > 0.0 ? 0 : 1;
    damped = damped || s.damping != 0.0;
  }
  if (zero_k) {
    not_modelled.push_back("zero-stiffness springs: " + std::to_string(zero_k) +
                           " springs with ks = 0 have no position constraint and are left out");
  }
  if (damped) {
    not_modelled.push_back("spring damping: the classic soft body has no per-link damping; it scales every velocity by "
                           "(1 - kDP) each step, kDP = " + note_number(options.kdp));
  }
  if (scene.integrator != IntegratorKind::Symplectic) {
    not_modelled.push_back(std::string("integrator ") + integrator_name(scene.integrator) +
                           ": the classic soft body integrates semi-implicitly and then projects positions");
  }
  if (scene.forces.air_drag && *scene.forces.air_drag != 0.0) {
    not_modelled.push_back("air_drag: no linear force -c v; Bullet's aerodynamic drag (kDG) is quadratic in velocity "
                           "and acts through faces; not applied (kDP = " + note_number(options.kdp) + " damps instead)");
  }
  if (scene.forces.wind) {
    not_modelled.push_back("wind: Bullet's wind is a velocity acting through the aerodynamic model, not a constant "
                           "force per node; not applied");
  }
}

void ClassicSoftBody::Impl::report_unmodelled() {
  report_forces();
  if (!scene.planes.empty()) {
    not_modelled.push_back("bounded planes: modelled as static boxes (thickness " + note_number(options.plane_thickness) +
                           " m) behind each plane; nodes rest about the collision margin (" +
                           note_number(options.collision_margin) +
                           " m) off the face; contacts are position corrections through Bullet's sparse "
                           "signed-distance field, no time of contact");
    not_modelled.push_back("per-particle elasticity: the classic soft body's rigid contacts are inelastic");
    not_modelled.push_back("plane friction: Bullet's contact friction (kDF times the plane's friction), not core's "
                           "per-step (1 - mu) scaling");
  }
  if (options.self_collision) {
    const std::string clusters = options.self_collision_clusters == 0
                                     ? std::string("one cluster per triangle")
                                     : std::to_string(options.self_collision_clusters) + " clusters";
    not_modelled.push_back("self-collision: Bullet's cluster-cluster contacts (CollideCL_SS on the body against "
                           "itself, " + clusters + "), not core's triangle tests and GIA response");
  }
}

ClassicSoftBody::Impl::~Impl() {
  if (world) {
    planes.remove(*world);
    if (body) world->removeSoftBody(body);
  }
  delete body;
  world.reset();
}

ClassicSoftBody::ClassicSoftBody(const Scene& scene, const ClassicSoftBodyOptions& options)
    : impl_(std::make_unique<Impl>(scene, options)) {}
ClassicSoftBody::~ClassicSoftBody() = default;
ClassicSoftBody::ClassicSoftBody(ClassicSoftBody&&) noexcept = default;
ClassicSoftBody& ClassicSoftBody::operator=(ClassicSoftBody&&) noexcept = default;

bool ClassicSoftBody::step() {
  Impl& m = *impl_;
  if (m.unstable) return false;
  const double h = m.scene.dt;
  const int substeps = m.world->stepSimulation(h, 1, h);
  if (substeps != 1) throw std::logic_error("ClassicSoftBody: Bullet took " + std::to_string(substeps) + " internal steps");
  if (m.options.self_collision) {
    // What btSoftRigidDynamicsWorld's own self-collision pass would do if CL_SELF worked.
    btSoftColliders::CollideCL_SS collide;
    collide.ProcessSoftSoft(m.body, m.body);
  }
  ++m.steps;
  m.unstable = !nodes_finite(*m.body, m.scene.particles.size());
  return !m.unstable;
}

std::vector<Vec3> ClassicSoftBody::positions() const { return node_positions(*impl_->body, impl_->scene.particles.size()); }
std::vector<Vec3> ClassicSoftBody::velocities() const { return node_velocities(*impl_->body, impl_->scene.particles.size()); }
std::vector<std::string> ClassicSoftBody::not_modelled() const { return impl_->not_modelled; }
double ClassicSoftBody::time() const { return static_cast<double>(impl_->steps) * impl_->scene.dt; }
long long ClassicSoftBody::steps_done() const { return impl_->steps; }
const ClassicSoftBodyOptions& ClassicSoftBody::options() const { return impl_->options; }
double ClassicSoftBody::plane_contact_offset() const { return impl_->planes.contact_offset(); }

GuardedRun run_classic_soft_body(const Scene& scene, double h, double seconds, const ClassicSoftBodyOptions& options,
                                 double stray_limit) {
  if (!(h > 0.0) || !(seconds >= 0.0)) throw std::invalid_argument("run_classic_soft_body: h must be positive, seconds >= 0");
  Scene s = scene;
  s.dt = h;
  s.integrator = IntegratorKind::Symplectic;  // the scene's own integrator is not this run's
  ClassicSoftBody body(s, options);
  return run_guarded(body, scene.particles.x, fixed_time_steps(seconds, h), stray_limit);
}

}  // namespace tecido::reference
