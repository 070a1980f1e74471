// Segment against a solid box in its own frame: hand-worked entries and faces, moving along a
// face, thin boxes at long segments, and the deepest point of a segment inside (the seed's
// springs cutting through a block, fig. 10).
#include "core/geometry/segment_box.h"

#include <gtest/gtest.h>

namespace tecido {
namespace {

const Vec3 kUnit(1, 1, 1);

TEST(SegmentBox, DropThroughTheTopFace) {
  // (0, 0, 3) -> (0, 0, -3) reaches z = 1 at s = 1/3, through face 5 (+z).
  const BoxEntry e = segment_enters_box(Vec3(0, 0, 3), Vec3(0, 0, -3), kUnit);
  ASSERT_TRUE(e.hit);
  EXPECT_NEAR(e.s, 1.0 / 3.0, 1e-15);
  EXPECT_EQ(e.face, 5);
}

TEST(SegmentBox, SideEntryNamesItsFace) {
  const BoxEntry e = segment_enters_box(Vec3(3, 0.5, -0.5), Vec3(0, 0.5, -0.5), kUnit);
  ASSERT_TRUE(e.hit);
  EXPECT_NEAR(e.s, 2.0 / 3.0, 1e-15);
  EXPECT_EQ(e.face, 1);  // +x
  const BoxEntry f = segment_enters_box(Vec3(0, -4, 0), Vec3(0, 0, 0), Vec3(1, 2, 3));
  ASSERT_TRUE(f.hit);
  EXPECT_DOUBLE_EQ(f.s, 0.5);
  EXPECT_EQ(f.face, 2);  // -y
}

TEST(SegmentBox, AlongAFaceOrAnEdgeIsNoHit) {
  EXPECT_FALSE(segment_enters_box(Vec3(-2, 0, 1), Vec3(2, 0, 1), kUnit).hit);   // in the plane z = 1
  EXPECT_FALSE(segment_enters_box(Vec3(-2, 1, 1), Vec3(2, 1, 1), kUnit).hit);   // along an edge
  EXPECT_FALSE(segment_enters_box(Vec3(0, 0, 1), Vec3(0, 0, 2), kUnit).hit);    // leaving the top face
  EXPECT_FALSE(segment_enters_box(Vec3(0, 0, 2), Vec3(0, 0, 1), kUnit).hit);    // ending on it
  EXPECT_FALSE(segment_enters_box(Vec3(0.5, 0, 1.5), Vec3(1.5, 0, 0.5), kUnit).hit);  // passes the edge x = z = 1
}

TEST(SegmentBox, StartingOnAFaceMovingInIsAtZero) {
  const BoxEntry e = segment_enters_box(Vec3(0.2, 0.3, 1), Vec3(0.2, 0.3, 0.9), kUnit);
  ASSERT_TRUE(e.hit);
  EXPECT_EQ(e.s, 0.0);
  EXPECT_EQ(e.face, 5);
}

TEST(SegmentBox, ThinBoxAtHugeSegmentsIsNotTunnelled) {
  const Vec3 h(1, 1, 1e-6);
  for (double len : {1.0, 1e3, 1e6}) {
    const BoxEntry e = segment_enters_box(Vec3(0.1, 0.2, len), Vec3(0.1, 0.2, -len), h);
    ASSERT_TRUE(e.hit) << len;
    EXPECT_EQ(e.face, 5);
    EXPECT_NEAR(e.s, 0.5 * (1.0 - 1e-6 / len), 1e-15) << len;
  }
}

TEST(SegmentBox, EndInsideIsAlwaysAHit) {
  const BoxEntry e = segment_enters_box(Vec3(0.5, 0.5, 0.5), Vec3(0.5, 0.5, 0.25), kUnit);
  ASSERT_TRUE(e.hit);
  EXPECT_EQ(e.face, 1);  // nearest face of the start point, which is inside: a tie of x and y, x first
}

TEST(SegmentBox, DepthOfTheDeepestPoint) {
  // Through the centre along z: the centre is 1 from every face.
  EXPECT_DOUBLE_EQ(segment_box_depth(Vec3(0, 0, 3), Vec3(0, 0, -3), kUnit), 1.0);
  // A chord across the corner x = z = 1: (0.4 + 1.1 s, 0, 1.5 - 1.1 s); at s = 1/2 both x and z
  // are 0.95, 0.05 from their faces: the cut's depth.
  EXPECT_NEAR(segment_box_depth(Vec3(0.4, 0, 1.5), Vec3(1.5, 0, 0.4), kUnit), 0.05, 1e-15);
  // Passing the edge outside: no depth.
  EXPECT_EQ(segment_box_depth(Vec3(0.5, 0, 1.5), Vec3(1.5, 0, 0.5), kUnit), 0.0);
  EXPECT_EQ(segment_box_depth(Vec3(3, 3, 3), Vec3(4, 4, 4), kUnit), 0.0);
}

TEST(SegmentBox, ProjectionAndNearestFace) {
  EXPECT_EQ(nearest_box_face(Vec3(0.1, -0.95, 0.2), kUnit), 2);
  EXPECT_EQ(project_on_box_face(Vec3(3, 0.5, -2), kUnit, 1), Vec3(1, 0.5, -1));
  EXPECT_EQ(box_face_normal(4), Vec3(0, 0, -1));
}

}  // namespace
}  // namespace tecido
