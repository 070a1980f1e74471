// The springs-through-an-obstacle count on hand-worked segments: through the middle of a box,
// lying on its face (not through), cutting its edge, a rotated box, a sphere's chord against its
// tangent, a moving sphere at two times, a triangle crossed inside, on its edge and not reached.
#include "core/dynamics/springs_through_obstacle.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido {
namespace {

Obstacle box(const Vec3& h) {
  Obstacle o;
  o.kind = ObstacleKind::Box;
  o.half_extents = h;
  return o;
}

TEST(SpringsThroughObstacle, BoxThroughOnTheFaceAndAcrossTheEdge) {
  const Obstacle o = box(Vec3(0.5, 0.5, 0.5));
  EXPECT_TRUE(segment_through_obstacle(o, 0.0, Vec3(-1, 0, 0), Vec3(1, 0, 0)));
  EXPECT_FALSE(segment_through_obstacle(o, 0.0, Vec3(-1, 0, 0.5), Vec3(1, 0, 0.5)));  // on the top face
  EXPECT_TRUE(segment_through_obstacle(o, 0.0, Vec3(-1, 0, 0.49), Vec3(1, 0, 0.49)));
  // From beside the box (x = 0.6) up over the top edge: at x = 0.5, z = 0.3 + 0.3 / 6 = 0.35 < 0.5.
  EXPECT_TRUE(segment_through_obstacle(o, 0.0, Vec3(0.6, 0, 0.3), Vec3(0, 0, 0.6)));
  // The same slope 0.1 higher: at x = 0.5, z = 0.55, above the edge; at x = 0, z = 0.85.
  EXPECT_FALSE(segment_through_obstacle(o, 0.0, Vec3(0.6, 0, 0.5), Vec3(0, 0, 0.8)));
  // Ends inside the box count too (the segment enters the open box).
  EXPECT_TRUE(segment_through_obstacle(o, 0.0, Vec3(0, 0, 0), Vec3(0.1, 0, 0)));
}

TEST(SpringsThroughObstacle, RotatedBoxReachesFurtherAlongItsDiagonal) {
  // Turned 45 degrees about z, the box's corner reaches y = 0.5 sqrt 2 = 0.707.
  Obstacle o = box(Vec3(0.5, 0.5, 0.5));
  const Vec3 a(-1, 0.6, 0), b(1, 0.6, 0);
  EXPECT_FALSE(segment_through_obstacle(o, 0.0, a, b));
  o.orientation = Eigen::AngleAxisd(M_PI / 4, Vec3::UnitZ()).toRotationMatrix();
  EXPECT_TRUE(segment_through_obstacle(o, 0.0, a, b));
  EXPECT_FALSE(segment_through_obstacle(o, 0.0, Vec3(-1, 0.72, 0), Vec3(1, 0.72, 0)));
}

TEST(SpringsThroughObstacle, SphereChordAgainstTangentAndAMovingSphere) {
  Obstacle o;
  o.kind = ObstacleKind::Sphere;
  o.radius = 1.0;
  EXPECT_TRUE(segment_through_obstacle(o, 0.0, Vec3(-2, 0.99, 0), Vec3(2, 0.99, 0)));
  EXPECT_FALSE(segment_through_obstacle(o, 0.0, Vec3(-2, 1.0, 0), Vec3(2, 1.0, 0)));  // tangent
  EXPECT_FALSE(segment_through_obstacle(o, 0.0, Vec3(1.5, 0, 0), Vec3(3, 0, 0)));     // short of it
  o.velocity = Vec3(1, 0, 0);  // centre at (2, 0, 0) at t = 2
  const Vec3 a(1.5, 0, 0), b(3, 0, 0);
  EXPECT_FALSE(segment_through_obstacle(o, 0.0, a, b));
  EXPECT_TRUE(segment_through_obstacle(o, 2.0, a, b));
}

TEST(SpringsThroughObstacle, TriangleCrossedInsideOnItsEdgeAndNotReached) {
  Obstacle o;
  o.kind = ObstacleKind::Mesh;
  o.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  o.triangles = {{0, 1, 2}};
  EXPECT_TRUE(segment_through_obstacle(o, 0.0, Vec3(0.2, 0.2, -1), Vec3(0.2, 0.2, 1)));
  EXPECT_FALSE(segment_through_obstacle(o, 0.0, Vec3(0.5, 0.5, -1), Vec3(0.5, 0.5, 1)));  // on the edge
  EXPECT_FALSE(segment_through_obstacle(o, 0.0, Vec3(0.2, 0.2, 0.1), Vec3(0.2, 0.2, 1)));
  EXPECT_FALSE(segment_through_obstacle(o, 0.0, Vec3(0.2, 0.2, 0), Vec3(0.2, 0.2, 1)));  // ends on it
}

TEST(SpringsThroughObstacle, CountsEverySpringThatPassesThrough) {
  const Obstacle o = box(Vec3(0.5, 0.5, 0.5));
  // Four particles on a square of side 2 at z = 0.4 around the box, and one above it: the square's
  // sides pass beside the box (|y| = 1), its two diagonals through it, the springs to the top one
  // from the corners (-1,-1,0.4) -> (0,0,2): at |x| = 0.5, z = 1.2, above the box.
  const std::vector<Vec3> x = {Vec3(-1, -1, 0.4), Vec3(1, -1, 0.4), Vec3(1, 1, 0.4), Vec3(-1, 1, 0.4), Vec3(0, 0, 2)};
  std::vector<Spring> springs;
  for (int k = 0; k < 4; ++k) springs.push_back(Spring{k, (k + 1) % 4, 1.0, 2.0, 0.0});
  springs.push_back(Spring{0, 2, 1.0, 2.0, 0.0});
  springs.push_back(Spring{1, 3, 1.0, 2.0, 0.0});
  for (int k = 0; k < 4; ++k) springs.push_back(Spring{k, 4, 1.0, 2.0, 0.0});
  EXPECT_EQ(springs_through_obstacle(o, 0.0, springs, x), 2);
}

}  // namespace
}  // namespace tecido
