// The obstacles suite's inside test on hand-worked moving obstacles, and its cases on small runs.
#include "comparisons/io/source_dir.h"
#include "comparisons/suites/obstacles/analytic_cases.h"
#include "comparisons/suites/obstacles/block_scene.h"
#include "comparisons/suites/sweep.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::suites::obstacles {

TEST(ObstaclesInsideDepth, AMovingSphereIsWhereItsVelocityTookIt) {
  Obstacle o;
  o.kind = ObstacleKind::Sphere;
  o.radius = 1.0;
  o.velocity = Vec3(1, 0, 0);
  // At t = 2 the centre is at (2, 0, 0): (2.5, 0, 0) is 0.5 inside, (0, 0, 0) 1 outside.
  EXPECT_NEAR(inside_depth(o, 2.0, Vec3(2.5, 0, 0)), 0.5, 1e-15);
  EXPECT_NEAR(inside_depth(o, 2.0, Vec3(0, 0, 0)), -1.0, 1e-15);
}

TEST(ObstaclesInsideDepth, ASpinningBoxIsMeasuredInItsFrameAtThatTime) {
  Obstacle o;
  o.kind = ObstacleKind::Box;
  o.half_extents = Vec3(1.0, 0.1, 1.0);
  o.angular_velocity = Vec3(0, 0, M_PI / 2);  // a quarter turn per second
  // t = 0: (0, 0.9, 0) lies 0.8 outside the thin side; t = 1: the long axis is along y, and the
  // point is 0.1 inside (min(1 - 0.9, 0.1 - 0, 1 - 0)).
  EXPECT_NEAR(inside_depth(o, 0.0, Vec3(0, 0.9, 0)), -0.8, 1e-12);
  EXPECT_NEAR(inside_depth(o, 1.0, Vec3(0, 0.9, 0)), 0.1, 1e-12);
}

TEST(ObstaclesCases, AFastParticleAtATenSecondStepBouncesOffTheThinBox) {
  const io::Json r = fast_case(settings(true), "thin-box", 10.0);
  EXPECT_EQ(r.at("steps_inside").get<long long>(), 0);
  EXPECT_EQ(r.at("tunnelled").get<long long>(), 0);
  EXPECT_GE(r.at("contacts").get<long long>(), 1);
  EXPECT_TRUE(r.at("unstable").is_null());
}

TEST(ObstaclesCases, AnUnknownSceneOrObstacleThrows) {
  EXPECT_THROW(fast_case(settings(true), "no-such-scene", 1.0), std::invalid_argument);
  EXPECT_THROW(rest_case(settings(true), "cone"), std::invalid_argument);
}

TEST(ObstaclesScenes, TheBlockScenesAreTheSeedsCountsOverTheBlock) {
  const Settings s = settings(true);
  const std::string data = std::string(TECIDO_SOURCE_DIR) + "/data";
  for (int n : s.block_sides) {
    const Scene sc = block_scene(s, data, n, true);
    EXPECT_EQ(sc.particles.size(), static_cast<std::size_t>(n * n));
    EXPECT_TRUE(sc.edge_contacts);
    EXPECT_FALSE(block_scene(s, data, n, false).edge_contacts);
    ASSERT_EQ(sc.obstacles.size(), 1u);
    // The files: gravity -y, the block's top at y = 0.75, the cloth flat at y = 1.0.
    EXPECT_TRUE(up_of(sc).isApprox(Vec3::UnitY()));
    EXPECT_NEAR(initial_gap(sc), 0.25, 1e-12);
    bool over = false;
    EXPECT_NEAR(height_above_top(block_of(sc), up_of(sc), Vec3(0.1, 0.8, -0.2), &over), 0.05, 1e-12);
    EXPECT_TRUE(over);
    height_above_top(block_of(sc), up_of(sc), Vec3(0.3, 0.8, 0), &over);
    EXPECT_FALSE(over);
    // Type B (one edge apart) and type A (two apart) springs, every one stiff.
    const std::size_t b = 2 * n * (n - 1) + 2 * (n - 1) * (n - 1), a = 2 * n * (n - 2) + 2 * (n - 2) * (n - 2);
    EXPECT_EQ(stiff_springs(sc).size(), a + b);
  }
  EXPECT_THROW(block_scene(s, data, 7, false), std::invalid_argument);
  const Scene sphere = sphere_scene(s, data);
  EXPECT_EQ(sphere.obstacles.front().kind, ObstacleKind::Sphere);
  EXPECT_NEAR(initial_gap(sphere), 0.2, 1e-12);  // the cloth at y = 0.8 over a top at 0.3 + 0.3
  EXPECT_EQ(run_steps(s, sphere), std::llround(0.6 / sphere.dt));
  EXPECT_EQ(run_steps(settings(false), sphere), sphere.steps);
}

}  // namespace tecido::suites::obstacles
