#pragma once
/// A small rigid sphere dropped on a static plane in Bullet's rigid-body world
/// (btDiscreteDynamicsWorld, btSphereShape on btStaticPlaneShape, double build): the
/// engine people use for particles-as-spheres, compared with core's bisected point contact.
/// Only core types cross this header; Bullet stays inside bullet_rigid_drop.cpp.
namespace tecido::reference {

struct RigidDropResult {
  double contact_time = -1.0;  ///< first step end at which the sphere touched the plane [s] (-1: never)
  double rebound_apex = -1.0;  ///< highest centre height after the first contact, minus the radius [m]
  double radius = 0.0;
};

/// Drops a sphere of `radius` whose lowest point starts `height` above the plane z = 0, with
/// vertical speed vz0, under gravity g (positive, along -z), restitution `restitution` on both
/// bodies (Bullet multiplies them, so the sphere gets sqrt(k) and the plane sqrt(k)), no
/// friction, stepping `dt` (one internal step each) for `duration` seconds.
RigidDropResult bullet_sphere_drop(double height, double vz0, double g, double restitution, double radius, double dt,
                                   double duration);

}  // namespace tecido::reference
