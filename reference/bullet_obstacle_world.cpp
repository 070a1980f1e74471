// Bullet's classic soft body with rigid obstacles. The only unit that includes Bullet headers for
// it; built in the tecido_bullet library with the float64 Bullet (BT_USE_DOUBLE_PRECISION private).
// The soft body is set up as in bullet_softbody.cpp (nodes, links and faces in core's numbering,
// rest lengths written after Bullet's one-time reset, gravity in both the world and its
// btSoftBodyWorldInfo); the set-up facts it relies on are listed there.
#include "reference/bullet_obstacle_world.h"

#include "core/geometry/obstacle_pose.h"
#include "reference/bullet_common.h"

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/CollisionShapes/btTriangleMesh.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <LinearMath/btDefaultMotionState.h>

#include <algorithm>
#include <stdexcept>

static_assert(sizeof(btScalar) == sizeof(double), "the Bullet adapters need the float64 Bullet build");

namespace tecido::reference {

namespace {

btTransform pose_transform(const ObstaclePose& pose) {
  const Eigen::Matrix3d& r = pose.rotation;
  btTransform tr;
  tr.setBasis(btMatrix3x3(r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2), r(2, 0), r(2, 1), r(2, 2)));
  tr.setOrigin(to_bt(pose.center));
  return tr;
}

}  // namespace

struct BulletObstacleWorld::Impl {
  Scene scene;
  ObstacleWorldOptions options;
  std::vector<std::string> not_modelled;

  btSoftBodyRigidBodyCollisionConfiguration collision_config;
  std::unique_ptr<btCollisionDispatcher> dispatcher;
  std::unique_ptr<btDbvtBroadphase> broadphase;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver;
  std::unique_ptr<btSoftRigidDynamicsWorld> world;
  btSoftBody* body = nullptr;  // owned; deleted after removal from the world
  PlaneBoxes planes;
  std::vector<std::unique_ptr<btTriangleMesh>> meshes;
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btDefaultMotionState>> states;
  std::vector<std::unique_ptr<btRigidBody>> rigid;  // one per scene obstacle, in order

  long long steps = 0;
  bool unstable = false;

  Impl(const Scene& s, const ObstacleWorldOptions& o);
  ~Impl();
  void build_world();
  void build_body();
  std::unique_ptr<btCollisionShape> shape_of(const Obstacle& o);
  void add_obstacle(const Obstacle& o);
  void report();
};

BulletObstacleWorld::Impl::Impl(const Scene& s, const ObstacleWorldOptions& o) : scene(s), options(o) {
  if (!(scene.dt > 0.0)) throw std::invalid_argument("BulletObstacleWorld: scene.dt must be positive");
  if (!(options.klst > 0.0 && options.klst <= 1.0)) throw std::invalid_argument("BulletObstacleWorld: klst in (0, 1]");
  const int np = static_cast<int>(scene.particles.size());
  for (const Spring& sp : scene.forces.springs)
    if (sp.i < 0 || sp.j < 0 || sp.i >= np || sp.j >= np || sp.i == sp.j)
      throw std::invalid_argument("BulletObstacleWorld: spring with an invalid end");
  build_world();
  build_body();
  planes.add(*world, scene, 0.1, options.collision_margin, not_modelled);
  for (const Obstacle& ob : scene.obstacles) add_obstacle(ob);
  report();
}

void BulletObstacleWorld::Impl::build_world() {
  dispatcher = std::make_unique<btCollisionDispatcher>(&collision_config);
  broadphase = std::make_unique<btDbvtBroadphase>();
  solver = std::make_unique<btSequentialImpulseConstraintSolver>();
  world = std::make_unique<btSoftRigidDynamicsWorld>(dispatcher.get(), broadphase.get(), solver.get(), &collision_config);
  const Vec3 g = scene.forces.gravity.value_or(Vec3::Zero());
  world->setGravity(to_bt(g));
  btSoftBodyWorldInfo& info = world->getWorldInfo();
  info.m_gravity = to_bt(g);
  info.air_density = 0;
  info.water_density = 0;
  info.m_sparsesdf.setDefaultVoxelsz(options.voxel_size);
  info.m_sparsesdf.Initialize();
}

void BulletObstacleWorld::Impl::build_body() {
  body = new btSoftBody(&world->getWorldInfo(), 0, nullptr, nullptr);
  body->getCollisionShape()->setMargin(options.collision_margin);
  append_nodes(*body, scene.particles);
  double k_max = 0.0;
  for (const Spring& sp : scene.forces.springs) k_max = std::max(k_max, sp.stiffness);
  std::vector<double> rest;
  for (const Spring& sp : scene.forces.springs) {
    if (!(sp.stiffness > 0.0)) continue;
    btSoftBody::Material* mat = body->appendMaterial();
    mat->m_kLST = options.klst * sp.stiffness / k_max;
    body->appendLink(sp.i, sp.j, mat, false);
    rest.push_back(sp.rest_length);
  }
  for (const auto& t : scene.triangles) body->appendFace(t[0], t[1], t[2]);
  body->m_cfg.piterations = options.piterations;
  body->m_cfg.kDP = options.kdp;
  body->m_cfg.kDG = 0;
  body->m_cfg.kLF = 0;
  body->m_cfg.kDF = 1;  // times the obstacle's friction
  body->m_cfg.kCHR = 1;
  body->m_cfg.kKHR = 1;
  body->m_cfg.collisions = btSoftBody::fCollision::SDF_RS;
  body->setActivationState(DISABLE_DEACTIVATION);
  world->addSoftBody(body);
  freeze_rest_lengths(*body, rest);
}

std::unique_ptr<btCollisionShape> BulletObstacleWorld::Impl::shape_of(const Obstacle& o) {
  if (o.kind == ObstacleKind::Sphere) return std::make_unique<btSphereShape>(o.radius);
  if (o.kind == ObstacleKind::Box) {
    auto box = std::make_unique<btBoxShape>(to_bt(o.half_extents));
    box->setMargin(std::min(0.04, 0.25 * o.half_extents.minCoeff()));  // faces stay at the half extents
    return box;
  }
  auto mesh = std::make_unique<btTriangleMesh>();
  for (const auto& t : o.triangles)
    mesh->addTriangle(to_bt(o.vertices[t[0]] - o.center), to_bt(o.vertices[t[1]] - o.center),
                      to_bt(o.vertices[t[2]] - o.center));
  auto shape = std::make_unique<btBvhTriangleMeshShape>(mesh.get(), true);
  meshes.push_back(std::move(mesh));
  return shape;
}

void BulletObstacleWorld::Impl::add_obstacle(const Obstacle& o) {
  auto shape = shape_of(o);
  ObstaclePose pose;
  obstacle_pose_at(o, 0.0, pose);
  auto state = std::make_unique<btDefaultMotionState>(pose_transform(pose));
  btRigidBody::btRigidBodyConstructionInfo info(0.0, state.get(), shape.get(), btVector3(0, 0, 0));
  info.m_friction = o.friction;
  info.m_restitution = 0.0;
  auto rb = std::make_unique<btRigidBody>(info);
  if (o.moving() && o.frames.empty()) {
    rb->setCollisionFlags(rb->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
    rb->setActivationState(DISABLE_DEACTIVATION);
  }
  world->addRigidBody(rb.get());
  shapes.push_back(std::move(shape));
  states.push_back(std::move(state));
  rigid.push_back(std::move(rb));
}

void BulletObstacleWorld::Impl::report() {
  if (!scene.forces.springs.empty())
    not_modelled.push_back("Hooke springs: links are position constraints (kLST = " + note_number(options.klst) +
                           ", piterations = " + std::to_string(options.piterations) + "), not forces ks (|x| - l)");
  if (scene.forces.air_drag && *scene.forces.air_drag != 0.0)
    not_modelled.push_back("air_drag: no linear drag force is applied (kDG = 0, kDP = " + note_number(options.kdp) + ")");
  if (std::any_of(scene.forces.springs.begin(), scene.forces.springs.end(), [](const Spring& sp) { return sp.damping != 0.0; }))
    not_modelled.push_back("spring damping: links have no per-link damping");
  if (scene.obstacles.empty()) return;
  not_modelled.push_back("hard obstacle contact: nodes are pushed out through a sparse signed-distance field (voxel " +
                         note_number(options.voxel_size) + " m, trilinear) and rest about the margin (" +
                         note_number(options.collision_margin) + " m) off the surface; no time of contact");
  not_modelled.push_back("per-particle and per-obstacle elasticity: the classic soft body's rigid contacts are inelastic");
  not_modelled.push_back("obstacle friction: Bullet's contact friction (kDF = 1 times the obstacle's), not core's "
                         "per-step (1 - mu) scaling");
  if (scene.edge_contacts)
    not_modelled.push_back("edge_contacts: only nodes collide with rigid bodies (SDF_RS); springs pass over edges");
  for (const Obstacle& o : scene.obstacles) {
    if (o.kind == ObstacleKind::Mesh)
      not_modelled.push_back("mesh obstacle: the sparse SDF has a distance for convex shapes only, so nodes never touch "
                             "a btBvhTriangleMeshShape");
    if (!o.frames.empty()) not_modelled.push_back("mesh keyframes: the rigid mesh stays at its first frame");
  }
}

BulletObstacleWorld::Impl::~Impl() {
  if (world) {
    planes.remove(*world);
    for (auto& rb : rigid) world->removeRigidBody(rb.get());
    if (body) world->removeSoftBody(body);
  }
  delete body;
  world.reset();
}

BulletObstacleWorld::BulletObstacleWorld(const Scene& scene, const ObstacleWorldOptions& options)
    : impl_(std::make_unique<Impl>(scene, options)) {}
BulletObstacleWorld::~BulletObstacleWorld() = default;
BulletObstacleWorld::BulletObstacleWorld(BulletObstacleWorld&&) noexcept = default;
BulletObstacleWorld& BulletObstacleWorld::operator=(BulletObstacleWorld&&) noexcept = default;

bool BulletObstacleWorld::step() {
  Impl& m = *impl_;
  if (m.unstable) return false;
  const double h = m.scene.dt;
  const double t1 = static_cast<double>(m.steps + 1) * h;
  ObstaclePose pose;
  for (std::size_t k = 0; k < m.scene.obstacles.size(); ++k) {
    if (!m.rigid[k]->isKinematicObject()) continue;
    obstacle_pose_at(m.scene.obstacles[k], t1, pose);
    m.states[k]->setWorldTransform(pose_transform(pose));
  }
  const int substeps = m.world->stepSimulation(h, 1, h);
  if (substeps != 1) throw std::logic_error("BulletObstacleWorld: Bullet took " + std::to_string(substeps) + " steps");
  ++m.steps;
  m.unstable = !nodes_finite(*m.body, m.scene.particles.size());
  return !m.unstable;
}

std::vector<Vec3> BulletObstacleWorld::positions() const {
  return node_positions(*impl_->body, impl_->scene.particles.size());
}
std::vector<Vec3> BulletObstacleWorld::velocities() const {
  return node_velocities(*impl_->body, impl_->scene.particles.size());
}
std::vector<std::string> BulletObstacleWorld::not_modelled() const { return impl_->not_modelled; }
double BulletObstacleWorld::time() const { return static_cast<double>(impl_->steps) * impl_->scene.dt; }
long long BulletObstacleWorld::steps_done() const { return impl_->steps; }
double BulletObstacleWorld::contact_distance() const { return impl_->options.collision_margin; }

}  // namespace tecido::reference
