// The suite's own measurement of springs through a box, on hand-built segments.
#include "comparisons/suites/obstacles/box_interior.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>

namespace tecido::suites::obstacles {

namespace {

OrientedBox unit_box() { return OrientedBox{Vec3::Zero(), Eigen::Matrix3d::Identity(), Vec3(1, 1, 1)}; }

}  // namespace

TEST(BoxInterior, ASegmentThroughTheCentreIsAsDeepAsTheHalfExtent) {
  EXPECT_DOUBLE_EQ(segment_box_interior_depth(Vec3(-2, 0, 0), Vec3(2, 0, 0), unit_box()), 1.0);
}

TEST(BoxInterior, ASegmentLyingOnAFaceIsNotInside) {
  EXPECT_LE(segment_box_interior_depth(Vec3(-2, 0, 1), Vec3(2, 0, 1), unit_box()), 0.0);
  EXPECT_LE(segment_box_interior_depth(Vec3(-0.5, 0, 1), Vec3(0.5, 0, 1), unit_box()), 0.0);
}

TEST(BoxInterior, ACutAcrossAnEdgeIsAsDeepAsItsMiddle) {
  // x + y = 1.5 in the plane z = 0: deepest at (0.75, 0.75, 0), depth 1 - 0.75 = 0.25.
  EXPECT_NEAR(segment_box_interior_depth(Vec3(0, 1.5, 0), Vec3(1.5, 0, 0), unit_box()), 0.25, 1e-15);
  // x + y = 2.5 passes outside the edge (x + y < 2 inside near it).
  EXPECT_LT(segment_box_interior_depth(Vec3(0.5, 2, 0), Vec3(2, 0.5, 0), unit_box()), 0.0);
}

TEST(BoxInterior, ARotatedBoxIsMeasuredInItsOwnFrame) {
  OrientedBox b = unit_box();
  b.rotation = Eigen::AngleAxisd(M_PI / 4, Vec3::UnitZ()).toRotationMatrix();
  // The line y = 1.2 crosses the diamond; deepest at x = 0: local (1.2/sqrt2, 1.2/sqrt2).
  EXPECT_NEAR(segment_box_interior_depth(Vec3(-3, 1.2, 0), Vec3(3, 1.2, 0), b), 1.0 - 1.2 / std::sqrt(2.0), 1e-12);
  // y = 1.5 > sqrt 2: outside.
  EXPECT_LT(segment_box_interior_depth(Vec3(-3, 1.5, 0), Vec3(3, 1.5, 0), b), 0.0);
  // A translated box.
  b.center = Vec3(10, 0, 0);
  EXPECT_NEAR(segment_box_interior_depth(Vec3(7, 0, 0), Vec3(13, 0, 0), b), 1.0, 1e-12);
}

TEST(BoxInterior, SpringsThroughTheBoxAreCountedAboveTheDepth) {
  // Four points: 0 and 1 on either side of the box (through, depth 1), 1 and 2 on the +x face
  // (on the surface, not through), 2 and 3 across a corner region 0.25 deep.
  const std::vector<Vec3> x = {Vec3(-2, 0, 0), Vec3(2, 0, 0), Vec3(1, 0.5, 0), Vec3(0, 1.5, 0), Vec3(1.5, 0, 0)};
  const std::vector<std::array<int, 2>> springs = {{0, 1}, {1, 2}, {3, 4}};
  double deepest = 0.0;
  EXPECT_EQ(springs_through_box(x, springs, unit_box(), 1e-9, &deepest), 2);
  EXPECT_DOUBLE_EQ(deepest, 1.0);
  EXPECT_EQ(springs_through_box(x, springs, unit_box(), 0.5, &deepest), 1);
  EXPECT_EQ(springs_through_box(x, springs, unit_box(), 1.0), 0);
}

TEST(BoxInterior, PointDepth) {
  EXPECT_DOUBLE_EQ(point_box_depth(Vec3(0.5, 0, 0), unit_box()), 0.5);
  EXPECT_DOUBLE_EQ(point_box_depth(Vec3(1, 0, 0), unit_box()), 0.0);
  EXPECT_LT(point_box_depth(Vec3(1.5, 0, 0), unit_box()), 0.0);
}

}  // namespace tecido::suites::obstacles
