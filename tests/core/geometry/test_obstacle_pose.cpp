// Poses of moving obstacles: translation, rotation about the centre, keyframes, and the surface
// velocity each gives.
#include "core/geometry/obstacle_pose.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido {
namespace {

TEST(ObstaclePose, TranslationAndRotation) {
  Obstacle box;
  box.kind = ObstacleKind::Box;
  box.center = Vec3(1, 0, 0);
  box.half_extents = Vec3(1, 0.1, 0.1);
  box.velocity = Vec3(0, 0, 2);
  box.angular_velocity = Vec3(0, 0, M_PI / 2);  // a quarter turn per second about z
  ObstaclePose p;
  obstacle_pose_at(box, 1.0, p);
  EXPECT_TRUE(p.center.isApprox(Vec3(1, 0, 2)));
  // The box's local x axis now points along world y.
  EXPECT_NEAR((p.rotation * Vec3::UnitX() - Vec3::UnitY()).norm(), 0.0, 1e-15);
  EXPECT_NEAR((p.to_world(Vec3(1, 0, 0)) - Vec3(1, 1, 2)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((p.to_local(Vec3(1, 1, 2)) - Vec3(1, 0, 0)).norm(), 0.0, 1e-15);
  // Surface velocity at the local x end: v + w x r = (0, 0, 2) + (pi/2) z x y = (-pi/2, 0, 2).
  EXPECT_NEAR((obstacle_surface_velocity(box, p, Vec3(1, 1, 2)) - Vec3(-M_PI / 2, 0, 2)).norm(), 0.0, 1e-15);
}

TEST(ObstaclePose, RigidMeshTurnsAboutItsPivot) {
  Obstacle m;
  m.kind = ObstacleKind::Mesh;
  m.vertices = {Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(2, 1, 0)};
  m.triangles = {{0, 1, 2}};
  m.center = Vec3(1, 0, 0);
  m.angular_velocity = Vec3(0, 0, M_PI);
  ObstaclePose p;
  obstacle_pose_at(m, 1.0, p);  // half a turn about (1, 0, 0)
  EXPECT_NEAR((p.vertices[0] - Vec3(0, 0, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((p.vertices[1] - Vec3(-1, 0, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((p.vertices[2] - Vec3(0, -1, 0)).norm(), 0.0, 1e-15);
}

TEST(ObstaclePose, KeyframesInterpolateAndHold) {
  Obstacle m;
  m.kind = ObstacleKind::Mesh;
  m.triangles = {{0, 1, 2}};
  m.frames = {{1.0, {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}}, {3.0, {Vec3(0, 0, 2), Vec3(1, 0, 2), Vec3(0, 1, 4)}}};
  m.vertices = m.frames[0].vertices;
  ObstaclePose p;
  obstacle_pose_at(m, 0.0, p);
  EXPECT_EQ(p.vertices[2], Vec3(0, 1, 0));
  EXPECT_EQ(p.vertex_velocity[2], Vec3::Zero());
  obstacle_pose_at(m, 2.0, p);
  EXPECT_EQ(p.vertices[0], Vec3(0, 0, 1));
  EXPECT_EQ(p.vertices[2], Vec3(0, 1, 2));
  EXPECT_EQ(p.vertex_velocity[2], Vec3(0, 0, 2));
  // The surface velocity at the triangle's centroid: the mean of its vertex velocities.
  const Vec3 u = obstacle_surface_velocity(m, p, Vec3::Zero(), 0, Vec3(1.0 / 3, 1.0 / 3, 1.0 / 3));
  EXPECT_NEAR((u - Vec3(0, 0, 4.0 / 3)).norm(), 0.0, 1e-15);
  obstacle_pose_at(m, 5.0, p);
  EXPECT_EQ(p.vertices[2], Vec3(0, 1, 4));
}

}  // namespace
}  // namespace tecido
