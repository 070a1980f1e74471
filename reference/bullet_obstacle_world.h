#pragma once
/// Bullet 3.24's classic soft body (as bullet_softbody.h: position-based links in a
/// btSoftRigidDynamicsWorld) with a Scene's obstacles as rigid bodies: a sphere as btSphereShape, a
/// box as btBoxShape, a mesh as btBvhTriangleMeshShape; static, or kinematic when the obstacle
/// moves (its pose at each step's end, obstacle_pose.h, written to the body before the step, so
/// Bullet derives the body's velocity from it). Only core types cross this header; Bullet stays
/// inside bullet_obstacle_world.cpp (double-precision build).
///
/// What Bullet does differently is listed by not_modelled(): nodes collide with rigid shapes
/// through a sparse signed-distance field sampled on a grid (voxel_size) and hold a margin off the
/// surface instead of a hard constraint; only convex shapes have a distance there, so a triangle
/// mesh gives no contact; only nodes collide (no spring against edge); contacts are inelastic;
/// keyframed meshes stay at their first frame.
#include "core/scene/scene.h"

#include <memory>
#include <string>
#include <vector>

namespace tecido::reference {

struct ObstacleWorldOptions {
  double klst = 1.0;               ///< kLST of the stiffest links (bullet_softbody.h)
  int piterations = 10;            ///< position-solver sweeps per step
  double kdp = 0.0;                ///< velocity damping per step
  double collision_margin = 1e-3;  ///< soft body's collision margin [m]: nodes rest about this far off a face
  double voxel_size = 0.25;        ///< sparse SDF cell size [m] (Bullet's default 0.25)
};

/// The classic soft body among rigid obstacles, with the stepping calls of every dynamics engine as
/// plain members (see DeformableTwin). Not copyable; movable.
class BulletObstacleWorld {
 public:
  /// Builds the world: nodes, links (scene springs with ks > 0, kLST = klst ks / ks_max) and faces
  /// in core's numbering; planes as static boxes (bullet_common.h); obstacles as above, friction
  /// the obstacle's (kDF = 1). Throws std::invalid_argument for a scene it cannot build.
  explicit BulletObstacleWorld(const Scene& scene, const ObstacleWorldOptions& options = {});
  ~BulletObstacleWorld();
  BulletObstacleWorld(BulletObstacleWorld&&) noexcept;
  BulletObstacleWorld& operator=(BulletObstacleWorld&&) noexcept;
  BulletObstacleWorld(const BulletObstacleWorld&) = delete;
  BulletObstacleWorld& operator=(const BulletObstacleWorld&) = delete;

  /// Moves kinematic obstacles to their poses at the step's end, then one stepSimulation(dt, 1, dt).
  /// False once a node position or velocity is not finite.
  bool step();
  std::vector<Vec3> positions() const;
  std::vector<Vec3> velocities() const;
  std::vector<std::string> not_modelled() const;
  double time() const;
  long long steps_done() const;
  /// The distance from a convex obstacle's surface at which a node is in contact [m] (the margin).
  double contact_distance() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tecido::reference
