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
//    the calibration builds a fresh body per trial instead;
//  - CL_SS | CL_SELF never runs in 3.24 (defaultCollisionHandler switches on the combined flag
//    value): self-collision keeps CL_SS, generates clusters and calls CollideCL_SS itself.
#include "reference/bullet_softbody.h"
#include "reference/guarded_run.h"
#include "reference/plane_box.h"

#include "core/dynamics/simulation.h"

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftBodyInternals.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
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

}  // namespace

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
  std::vector<std::unique_ptr<btBoxShape>> plane_shapes;
  std::vector<std::unique_ptr<btDefaultMotionState>> plane_states;
  std::vector<std::unique_ptr<btRigidBody>> plane_bodies;

  long long steps = 0;
  bool unstable = false;
  double contact_offset = 0.0;

  Impl(const Scene& s, const ClassicSoftBodyOptions& o);
  ~Impl();
  void build_links();
  void build_planes();
  void report_unmodelled();
};

ClassicSoftBody::Impl::Impl(const Scene& s, const ClassicSoftBodyOptions& o) : scene(s), options(o) {
  // Self-collision is switched on when the scene asks for a self-collision response (Bullet's
  // collider is a response; "none" in the scene means detection only), or by the options.
  if (s.self_collision && s.self_collision->response != SelfCollisionResponse::None) options.self_collision = true;
  if (!(scene.dt > 0.0)) throw std::invalid_argument("ClassicSoftBody: scene.dt must be positive");
  if (!(options.klst > 0.0 && options.klst <= 1.0)) throw std::invalid_argument("ClassicSoftBody: klst must be in (0, 1]");
  if (options.piterations < 1) throw std::invalid_argument("ClassicSoftBody: piterations must be >= 1");
  if (!(options.kdp >= 0.0 && options.kdp <= 1.0)) throw std::invalid_argument("ClassicSoftBody: kdp must be in [0, 1]");
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

  const auto& p = scene.particles;
  body = new btSoftBody(&info, 0, nullptr, nullptr);
  body->getCollisionShape()->setMargin(options.collision_margin);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double w = p.inv_mass[i];
    body->appendNode(to_bt(p.x[i]), w > 0.0 ? 1.0 / w : 0.0);
    btSoftBody::Node& n = body->m_nodes[body->m_nodes.size() - 1];
    n.m_im = w;
    n.m_v = to_bt(p.v[i]);
    n.m_vn = n.m_v;
  }
  build_links();
  const int np = static_cast<int>(p.size());
  for (const auto& t : scene.triangles) {
    if (t[0] < 0 || t[1] < 0 || t[2] < 0 || t[0] >= np || t[1] >= np || t[2] >= np)
      throw std::invalid_argument("ClassicSoftBody: triangle with an invalid particle index");
    body->appendFace(t[0], t[1], t[2]);
  }
  body->m_cfg.piterations = options.piterations;
  body->m_cfg.kDP = options.kdp;
  body->m_cfg.kDG = 0;  // no aerodynamic drag or lift
  body->m_cfg.kLF = 0;
  body->m_cfg.kDF = 1;  // times the collider's friction (= the plane's)
  body->m_cfg.kCHR = 1;
  body->m_cfg.kKHR = 1;
  body->m_cfg.collisions = btSoftBody::fCollision::SDF_RS;
  if (options.self_collision) {
    if (options.self_collision_clusters == 0 && scene.triangles.empty())
      throw std::invalid_argument("ClassicSoftBody: self-collision with one cluster per triangle needs triangles");
    body->m_cfg.collisions |= btSoftBody::fCollision::CL_SS;
    body->generateClusters(options.self_collision_clusters);
  }
  body->setActivationState(DISABLE_DEACTIVATION);
  world->addSoftBody(body);

  // Bullet's one-time update of runtime constants (would reset rest lengths at the first step),
  // then the scene's rest lengths.
  // (Bullet's own update would also rebuild the face tree bottom-up for VF_SS, which we never set;
  // that build does not terminate on a mesh whose faces are not edge-connected.)
  body->updateConstants();
  body->m_bUpdateRtCst = false;
  int link = 0;
  for (const Spring& sp : scene.forces.springs) {
    if (!(sp.stiffness > 0.0)) continue;  // not appended (build_links)
    btSoftBody::Link& l = body->m_links[link++];
    l.m_rl = sp.rest_length;
    l.m_c1 = l.m_rl * l.m_rl;
  }
  build_planes();
  report_unmodelled();
}

void ClassicSoftBody::Impl::build_links() {
  const auto& springs = scene.forces.springs;
  double k_max = 0.0;
  for (const Spring& s : springs) k_max = std::max(k_max, s.stiffness);
  // One material per distinct stiffness: kLST = options.klst * ks / ks_max.
  std::vector<std::pair<double, btSoftBody::Material*>> materials;
  for (const Spring& s : springs) {
    if (s.i < 0 || s.j < 0 || s.i >= body->m_nodes.size() || s.j >= body->m_nodes.size() || s.i == s.j)
      throw std::invalid_argument("ClassicSoftBody: spring with an invalid end");
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

void ClassicSoftBody::Impl::build_planes() {
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

void ClassicSoftBody::Impl::report_unmodelled() {
  const auto& springs = scene.forces.springs;
  if (!springs.empty()) {
    not_modelled.insert(not_modelled.begin(),
                        "Hooke springs: links are position constraints projected towards their rest length (kLST = " +
                            num(options.klst) + ", piterations = " + std::to_string(options.piterations) +
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
                           "(1 - kDP) each step, kDP = " + num(options.kdp));
  }
  if (scene.integrator != IntegratorKind::Symplectic) {
    not_modelled.push_back(std::string("integrator ") + integrator_name(scene.integrator) +
                           ": the classic soft body integrates semi-implicitly and then projects positions");
  }
  if (scene.forces.air_drag && *scene.forces.air_drag != 0.0) {
    not_modelled.push_back("air_drag: no linear force -c v; Bullet's aerodynamic drag (kDG) is quadratic in velocity "
                           "and acts through faces; not applied (kDP = " + num(options.kdp) + " damps instead)");
  }
  if (scene.forces.wind) {
    not_modelled.push_back("wind: Bullet's wind is a velocity acting through the aerodynamic model, not a constant "
                           "force per node; not applied");
  }
  if (!scene.planes.empty()) {
    not_modelled.push_back("bounded planes: modelled as static boxes (thickness " + num(options.plane_thickness) +
                           " m) behind each plane; nodes rest about the collision margin (" +
                           num(options.collision_margin) +
                           " m) off the face; contacts are position corrections through Bullet's sparse "
                           "signed-distance field, no time of contact");
    not_modelled.push_back("per-particle elasticity: the classic soft body's rigid contacts are inelastic");
    not_modelled.push_back("plane friction: Bullet's contact friction (kDF times the plane's friction), not core's "
                           "per-step (1 - mu) scaling");
  }
  if (options.self_collision) {
    not_modelled.push_back("self-collision: Bullet's cluster-cluster contacts (CollideCL_SS on the body against "
                           "itself, " + std::string(options.self_collision_clusters == 0 ? "one cluster per triangle"
                                                                                           : std::to_string(options.self_collision_clusters) + " clusters") +
                           "), not core's triangle tests and GIA response");
  }
}

ClassicSoftBody::Impl::~Impl() {
  if (world) {
    for (auto& rb : plane_bodies) world->removeRigidBody(rb.get());
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
  for (int i = 0; i < m.body->m_nodes.size(); ++i) {
    const btSoftBody::Node& n = m.body->m_nodes[i];
    if (!std::isfinite(n.m_x.x()) || !std::isfinite(n.m_x.y()) || !std::isfinite(n.m_x.z()) ||
        !std::isfinite(n.m_v.x()) || !std::isfinite(n.m_v.y()) || !std::isfinite(n.m_v.z())) {
      m.unstable = true;
      return false;
    }
  }
  return true;
}

std::vector<Vec3> ClassicSoftBody::positions() const {
  std::vector<Vec3> out;
  out.reserve(static_cast<std::size_t>(impl_->body->m_nodes.size()));
  for (int i = 0; i < impl_->body->m_nodes.size(); ++i) out.push_back(from_bt(impl_->body->m_nodes[i].m_x));
  return out;
}

std::vector<Vec3> ClassicSoftBody::velocities() const {
  std::vector<Vec3> out;
  out.reserve(static_cast<std::size_t>(impl_->body->m_nodes.size()));
  for (int i = 0; i < impl_->body->m_nodes.size(); ++i) out.push_back(from_bt(impl_->body->m_nodes[i].m_v));
  return out;
}

std::vector<std::string> ClassicSoftBody::not_modelled() const { return impl_->not_modelled; }
double ClassicSoftBody::time() const { return static_cast<double>(impl_->steps) * impl_->scene.dt; }
long long ClassicSoftBody::steps_done() const { return impl_->steps; }
const ClassicSoftBodyOptions& ClassicSoftBody::options() const { return impl_->options; }
double ClassicSoftBody::plane_contact_offset() const { return impl_->contact_offset; }

std::optional<std::vector<Vec3>> run_classic_soft_body(const Scene& scene, double h, double seconds,
                                                       const ClassicSoftBodyOptions& options, double stray_limit) {
  if (!(h > 0.0) || !(seconds >= 0.0)) throw std::invalid_argument("run_classic_soft_body: h must be positive, seconds >= 0");
  Scene s = scene;
  s.dt = h;
  s.integrator = IntegratorKind::Symplectic;  // the scene's own integrator is not this run's
  ClassicSoftBody body(s, options);
  return run_guarded(body, scene.particles.x, std::llround(seconds / h), stray_limit);
}

// ---- calibration ------------------------------------------------------------------------------

double mean_sag(const Scene& scene, const std::vector<Vec3>& x) {
  if (!scene.forces.gravity || !(scene.forces.gravity->norm() > 0.0))
    throw std::invalid_argument("mean_sag: the scene has no gravity");
  const auto& p = scene.particles;
  if (x.size() != p.size()) throw std::invalid_argument("mean_sag: positions do not match the scene's particles");
  const Vec3 down = scene.forces.gravity->normalized();
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.pinned[i] || p.inv_mass[i] == 0.0) continue;
    sum += (x[i] - p.x[i]).dot(down);
    ++n;
  }
  if (n == 0) throw std::invalid_argument("mean_sag: the scene has no free particle");
  return sum / static_cast<double>(n);
}

namespace {

double max_speed(const std::vector<Vec3>& v) {
  double m = 0.0;
  for (const Vec3& vi : v) m = std::max(m, vi.norm());
  return m;
}

struct Settled {
  std::vector<Vec3> x;
  bool settled = false;
};

Settled settle_core(const Scene& scene, const SagCalibrationOptions& o) {
  Scene s = scene;
  s.integrator = IntegratorKind::Symplectic;  // the equilibrium does not depend on the integrator
  if (!s.forces.air_drag || *s.forces.air_drag == 0.0) {
    double c = o.core_air_drag;
    if (!(c > 0.0)) {
      double m = 0.0;
      std::size_t n = 0;
      for (double w : s.particles.inv_mass) {
        if (w > 0.0) {
          m += 1.0 / w;
          ++n;
        }
      }
      c = 10.0 * m / static_cast<double>(std::max<std::size_t>(n, 1));
    }
    s.forces.air_drag = c;
  }
  Simulation sim(s);
  Settled r;
  const long long max_steps = static_cast<long long>(std::ceil(o.max_time / s.dt));
  for (long long k = 0; k < max_steps; ++k) {
    if (!sim.step()) break;
    if (max_speed(sim.particles().v) < o.rest_speed) {
      r.settled = true;
      break;
    }
  }
  r.x = sim.particles().x;
  return r;
}

Settled settle_classic(const Scene& scene, double klst, const SagCalibrationOptions& o) {
  ClassicSoftBodyOptions co;
  co.klst = klst;
  co.piterations = o.piterations;
  co.kdp = o.kdp;
  ClassicSoftBody sb(scene, co);
  Settled r;
  const long long max_steps = static_cast<long long>(std::ceil(o.max_time / scene.dt));
  for (long long k = 0; k < max_steps; ++k) {
    if (!sb.step()) break;
    if (max_speed(sb.velocities()) < o.rest_speed) {
      r.settled = true;
      break;
    }
  }
  r.x = sb.positions();
  return r;
}

}  // namespace

double calibrate_klst_for_sag(const Scene& scene, const SagCalibrationOptions& o, SagCalibration* result) {
  if (!(o.klst_min > 0.0 && o.klst_min < 1.0)) throw std::invalid_argument("calibrate_klst_for_sag: klst_min must be in (0, 1)");
  SagCalibration cal;
  cal.piterations = o.piterations;
  cal.kdp = o.kdp;
  cal.dt = scene.dt;
  const Settled core = settle_core(scene, o);
  cal.core_settled = core.settled;
  cal.core_sag = mean_sag(scene, core.x);
  if (!std::isfinite(cal.core_sag))
    throw std::runtime_error("calibrate_klst_for_sag: core went unstable while settling (dt " + num(scene.dt) +
                             " s too large for its springs?)");
  const double target = cal.core_sag;
  const double tol = o.relative_tolerance * std::abs(target);

  struct Trial {
    double klst, sag;
    bool settled;
    std::vector<Vec3> x;
  };
  auto run = [&](double k) {
    Settled s = settle_classic(scene, k, o);
    ++cal.evaluations;
    const double sag = mean_sag(scene, s.x);
    if (!std::isfinite(sag))
      throw std::runtime_error("calibrate_klst_for_sag: Bullet went unstable while settling with kLST = " + num(k));
    return Trial{k, sag, s.settled, std::move(s.x)};
  };
  Trial best{};
  auto consider = [&](const Trial& t) {
    if (cal.evaluations == 1 || std::abs(t.sag - target) < std::abs(best.sag - target)) best = t;
  };

  if (o.klst_guess > 0.0) {
    // Safeguarded secant on f(u) = log(sag(e^u) / target), u = log kLST, u in [log klst_min, 0].
    // f falls as u grows; the first secant slope is -1 (sag ~ 1/kLST). A bracket [u_soft, u_stiff]
    // (f >= 0 at u_soft, f <= 0 at u_stiff) is kept once both signs are seen, and a secant step
    // that leaves it is replaced by the bracket's midpoint.
    const double u_min = std::log(o.klst_min);
    const double log_target = std::log(target);
    auto f = [&](const Trial& t) { return std::log(t.sag) - log_target; };
    auto matched = [&] { return std::abs(best.sag - target) <= tol; };
    double soft = u_min, stiff = 0.0;
    bool have_soft = false, have_stiff = false;
    auto bracket = [&](double u, double fu) {
      if (fu >= 0.0 && (!have_soft || u > soft)) soft = u, have_soft = true;
      if (fu <= 0.0 && (!have_stiff || u < stiff)) stiff = u, have_stiff = true;
    };
    if (!(target > 0.0)) throw std::runtime_error("calibrate_klst_for_sag: core's sag is not positive; no kLST guess can match it");
    double u0 = std::clamp(std::log(o.klst_guess), u_min, 0.0);
    Trial t0 = run(std::exp(u0));
    consider(t0);
    if (!(t0.sag > 0.0)) throw std::runtime_error("calibrate_klst_for_sag: Bullet's sag is not positive at the kLST guess");
    double f0 = f(t0);
    bracket(u0, f0);
    double u1 = std::clamp(u0 + f0, u_min, 0.0);  // slope -1
    for (int it = 0; it < o.max_bisections && !matched() && u1 != u0; ++it) {
      Trial t1 = run(std::exp(u1));
      consider(t1);
      if (!(t1.sag > 0.0)) break;
      const double f1 = f(t1);
      bracket(u1, f1);
      if (std::abs(t1.sag - target) <= tol) break;
      const double slope = (f1 - f0) / (u1 - u0);
      double u2 = slope < 0.0 && std::isfinite(slope) ? u1 - f1 / slope : 0.5 * (soft + stiff);
      if (have_soft && have_stiff && !(u2 > soft && u2 < stiff)) u2 = 0.5 * (soft + stiff);
      u2 = std::clamp(u2, u_min, 0.0);
      u0 = u1;
      f0 = f1;
      u1 = u2;
    }
    cal.bracketed = matched() || (have_soft && have_stiff);
    cal.sag_at_klst_1 = std::nan("");
  } else {
    const Trial stiff = run(1.0);
    consider(stiff);
    cal.sag_at_klst_1 = stiff.sag;
    if (stiff.sag > target + tol) {
      // Even kLST = 1 sags more than core: Bullet cannot be as stiff with these piterations and dt.
    } else if (std::abs(stiff.sag - target) > tol) {
      const Trial soft = run(o.klst_min);
      consider(soft);
      if (soft.sag >= target - tol) {
        cal.bracketed = true;
        double lo = std::log(o.klst_min), hi = 0.0;  // sag(lo) >= target >= sag(hi)
        for (int it = 0; it < o.max_bisections && std::abs(best.sag - target) > tol; ++it) {
          const double mid = 0.5 * (lo + hi);
          const Trial t = run(std::exp(mid));
          consider(t);
          if (t.sag > target) {
            lo = mid;  // too soft: stiffer
          } else {
            hi = mid;
          }
        }
      }
    } else {
      cal.bracketed = true;
    }
  }
  cal.klst = best.klst;
  cal.bullet_sag = best.sag;
  cal.bullet_settled = best.settled;
  cal.sag_error = best.sag - target;
  double sum = 0.0;
  for (std::size_t i = 0; i < best.x.size(); ++i) {
    const double d = (best.x[i] - core.x[i]).norm();
    sum += d * d;
    cal.shape_max = std::max(cal.shape_max, d);
  }
  cal.shape_rms = best.x.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(best.x.size()));
  cal.relative_error = target != 0.0 ? std::abs(cal.sag_error) / std::abs(target) : std::abs(cal.sag_error);
  if (result) *result = cal;
  return cal.klst;
}

}  // namespace tecido::reference
