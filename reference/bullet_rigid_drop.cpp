// The only unit that includes Bullet's rigid-body world for the drop comparison.
#include "reference/bullet_rigid_drop.h"

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace tecido::reference {

RigidDropResult bullet_sphere_drop(double height, double vz0, double g, double restitution, double radius, double dt,
                                   double duration) {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
  world.setGravity(btVector3(0, 0, -g));

  btStaticPlaneShape plane_shape(btVector3(0, 0, 1), 0);
  btDefaultMotionState plane_state;
  btRigidBody::btRigidBodyConstructionInfo plane_info(0.0, &plane_state, &plane_shape);
  const double k = std::sqrt(std::max(0.0, restitution));
  plane_info.m_restitution = k;
  plane_info.m_friction = 0.0;
  btRigidBody plane(plane_info);
  world.addRigidBody(&plane);

  btSphereShape sphere_shape(radius);
  btTransform start;
  start.setIdentity();
  start.setOrigin(btVector3(0, 0, height + radius));
  btDefaultMotionState sphere_state(start);
  btVector3 inertia(0, 0, 0);
  sphere_shape.calculateLocalInertia(1.0, inertia);
  btRigidBody::btRigidBodyConstructionInfo sphere_info(1.0, &sphere_state, &sphere_shape, inertia);
  sphere_info.m_restitution = k;
  sphere_info.m_friction = 0.0;
  btRigidBody sphere(sphere_info);
  sphere.setLinearVelocity(btVector3(0, 0, vz0));
  sphere.setActivationState(DISABLE_DEACTIVATION);
  world.addRigidBody(&sphere);

  RigidDropResult r;
  r.radius = radius;
  const long long steps = std::llround(duration / dt);
  bool touched = false;
  double vz_prev = vz0;
  for (long long i = 1; i <= steps; ++i) {
    world.stepSimulation(dt, 1, dt);
    const double z = sphere.getCenterOfMassPosition().z() - radius;
    const double vz = sphere.getLinearVelocity().z();
    // Contact: the plane's impulse makes vz larger than gravity alone would (or the sphere is in).
    if (!touched && (vz > vz_prev - g * dt + 1e-9 || z <= 0.0)) {
      touched = true;
      r.contact_time = static_cast<double>(i) * dt;
      r.rebound_apex = z;
    } else if (touched) {
      r.rebound_apex = std::max(r.rebound_apex, z);
    }
    vz_prev = vz;
  }
  world.removeRigidBody(&sphere);
  world.removeRigidBody(&plane);
  return r;
}

}  // namespace tecido::reference
