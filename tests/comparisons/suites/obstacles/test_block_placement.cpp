// Where the block's edges fall against the cloth's grid (edge_insets) and which springs cross the
// top face's outline (springs_across_outline), on the two block scenes and hand-worked changes of
// them: the matched comparison's premise, computed and asserted.
#include "comparisons/io/source_dir.h"
#include "comparisons/suites/obstacles/block_scene.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::suites::obstacles {

namespace {

Scene scene_with(int n) {
  return block_scene(settings(true), std::string(TECIDO_SOURCE_DIR) + "/data", n, false);
}

void expect_insets(const Scene& sc, const std::array<double, 4>& want) {
  const std::array<double, 4> got = edge_insets(sc);
  for (std::size_t e = 0; e < 4; ++e) EXPECT_NEAR(got[e], want[e], 1e-12) << "edge " << e;
}

}  // namespace

TEST(ObstaclesBlockPlacement, BothScenesPlaceTheBlockMidwayBetweenColumns) {
  // 121: columns at -0.5 + 0.1 i, the edges +-0.25 between 0.2 and 0.3 (and -0.3 and -0.2);
  // 484: columns at -0.525 + 0.05 i, the edges between 0.225 and 0.275: both 0.5 spacings in.
  const Scene coarse = scene_with(11), fine = scene_with(22);
  expect_insets(coarse, {0.5, 0.5, 0.5, 0.5});
  expect_insets(fine, {0.5, 0.5, 0.5, 0.5});
  const auto a = edge_insets(coarse), b = edge_insets(fine);
  for (std::size_t e = 0; e < 4; ++e) EXPECT_NEAR(a[e], b[e], 1e-12);
  EXPECT_NE(coarse.cloth->spacing, fine.cloth->spacing);
}

TEST(ObstaclesBlockPlacement, TheOldOneMetre484ClothMetTheBlockElsewhere) {
  // 22 x 22 over 1 m (spacing 1/21, origin -0.5): the + edge at (0.25 + 0.5) x 21 = 15.75
  // spacings, 0.75 in from column 15; the - edge at 5.25, 0.75 in from column 6.
  Scene sc = scene_with(22);
  sc.cloth->spacing = 1.0 / 21.0;
  sc.cloth->origin = Vec3(-0.5, 1.0, -0.5);
  expect_insets(sc, {0.75, 0.75, 0.75, 0.75});
}

TEST(ObstaclesBlockPlacement, MovingOrResizingTheBlockMovesItsEdgesAgainstTheGrid) {
  Scene moved = scene_with(11);
  moved.obstacles.front().center.x() += 0.025;  // + edge at 0.275 (0.75 in), - edge at -0.225 (0.25 in)
  expect_insets(moved, {0.75, 0.25, 0.5, 0.5});
  Scene wide = scene_with(11);
  wide.obstacles.front().half_extents.x() = 0.3;  // the edges on the columns at +-0.3
  expect_insets(wide, {0.0, 0.0, 0.5, 0.5});
  Scene turned = scene_with(11);  // a quarter turn about y: the same box, its axes swapped
  turned.obstacles.front().orientation = Eigen::AngleAxisd(M_PI / 2, Vec3::UnitY()).toRotationMatrix();
  expect_insets(turned, {0.5, 0.5, 0.5, 0.5});
}

TEST(ObstaclesBlockPlacement, ABlockAskewToTheGridOrNoClothIsAnError) {
  Scene skew = scene_with(11);
  skew.obstacles.front().orientation = Eigen::AngleAxisd(0.5, Vec3::UnitY()).toRotationMatrix();
  EXPECT_THROW(edge_insets(skew), std::invalid_argument);
  Scene bare = scene_with(11);
  bare.cloth.reset();
  EXPECT_THROW(edge_insets(bare), std::invalid_argument);
}

TEST(ObstaclesBlockPlacement, SpringsAcrossTheOutlineCountedByHand) {
  // 121: the particles over the top are columns and rows 3..7 (a 5 x 5 set S in 11 x 11). For an
  // offset o, pairs with exactly one end in S = (pairs starting in S) + (ending in S) - 2 (both):
  // reach 1: along a row 25 + 25 - 2 x 20 = 10, a column 10, each diagonal 25 + 25 - 2 x 16 = 18;
  // reach 2: along a row 25 + 25 - 2 x 15 = 20, a column 20, each diagonal 25 + 25 - 2 x 9 = 32.
  // 10 + 10 + 18 + 18 + 20 + 20 + 32 + 32 = 160.
  EXPECT_EQ(springs_across_outline(scene_with(11)), 160);
  // 484: columns and rows 6..15 (10 x 10 in 22 x 22): reach 1: along a row 200 - 2 x 90 = 20, a
  // column 20, each diagonal 200 - 2 x 81 = 38, 116;
  // reach 2: along a row 200 - 2 x 80 = 40, a column 40, each diagonal 200 - 2 x 64 = 72: 224.
  EXPECT_EQ(springs_across_outline(scene_with(22)), 116 + 224);
}

}  // namespace tecido::suites::obstacles
