// The obstacle scenes of data/scenes (the seed's cloth on a block at 121 and 484 particles, a
// cloth dropped on a sphere, a curtain pushed by a moving sphere): each runs to its end, stable,
// and no free particle is inside any obstacle after any step (exact inside tests at the
// obstacle's pose at that time). The cloth on the sphere touches it first where the closed form
// says and it rests on the sphere; with edge contacts on, no spring of the 121-particle block scene passes through the block
// after any step; `tecido run --out` draws the moving sphere where it is at each frame; the
// block given as an OBJ mesh holds the cloth as the analytic block does.
#include "comparisons/io/source_dir.h"
#include "comparisons/io/scene_json.h"
#include "core/dynamics/springs_through_obstacle.h"
#include "core/geometry/obstacle_pose.h"
#include "core/geometry/segment_box.h"
#include "core/geometry/segment_sphere.h"
#include "core/simulation/simulation.h"
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>

namespace tecido {
namespace {

std::string scene_path(const std::string& name) { return std::string(TECIDO_SOURCE_DIR) + "/data/scenes/" + name; }

/// The first free particle inside an obstacle (exact tests at its pose at time t), or -1.
int first_inside(const Scene& s, const Particles& p, double t) {
  ObstaclePose pose;
  for (const Obstacle& o : s.obstacles) {
    obstacle_pose_at(o, t, pose);
    for (std::size_t i = 0; i < p.x.size(); ++i) {
      if (p.pinned[i]) continue;
      const bool inside = o.kind == ObstacleKind::Sphere ? inside_sphere(p.x[i] - pose.center, o.radius)
                          : o.kind == ObstacleKind::Box  ? inside_box(pose.to_local(p.x[i]), o.half_extents)
                                                         : false;
      if (inside) return static_cast<int>(i);
    }
  }
  return -1;
}

/// Runs the scene (its first `steps` steps, all when negative), asserting after every step that it is finite and no particle is
/// inside an obstacle; with `no_spring_through`, also that no spring passes through one.
Simulation run_checked(const Scene& s, bool no_spring_through = false, long long steps = -1) {
  Simulation sim(s);
  for (long long k = 0; k < (steps < 0 ? s.steps : steps); ++k) {
    EXPECT_TRUE(sim.step()) << "unstable at step " << k + 1;
    const int i = first_inside(s, sim.particles(), sim.time());
    EXPECT_EQ(i, -1) << "particle " << i << " inside after step " << k + 1;
    if (no_spring_through) {
      for (const Obstacle& o : s.obstacles)
        EXPECT_EQ(springs_through_obstacle(o, sim.time(), s.forces.springs, sim.particles().x), 0) << "step " << k + 1;
    }
    if (::testing::Test::HasFailure()) break;
  }
  return sim;
}

TEST(ObstacleScenes, BlockSceneAt121ParticlesRestsOnTheBlock) {
  const Scene s = io::load_scene(scene_path("seed_fig10_12_block_121.json"));
  ASSERT_EQ(s.particles.size(), 121u);
  ASSERT_FALSE(s.edge_contacts);
  const Simulation sim = run_checked(s);
  EXPECT_GT(sim.obstacle_contacts().counters().contacts, 0);
  // The particle over the block's centre rests on its top face (y = 0.75).
  EXPECT_NEAR(sim.particles().x[60].y(), 0.75, 1e-6);
}

TEST(ObstacleScenes, BlockSceneAt484ParticlesRestsOnTheBlock) {
  const Scene s = io::load_scene(scene_path("seed_fig11_13_block_484.json"));
  ASSERT_EQ(s.particles.size(), 484u);
  const Simulation sim = run_checked(s);
  EXPECT_GT(sim.obstacle_contacts().counters().contacts, 0);
}

TEST(ObstacleScenes, BlockSceneWithEdgeContactsKeepsEverySpringOut) {
  Scene s = io::load_scene(scene_path("seed_fig10_12_block_121.json"));
  s.edge_contacts = true;
  const Simulation sim = run_checked(s, /*no_spring_through=*/true);
  EXPECT_GT(sim.spring_box_contacts().counters().contacts, 0);
}

TEST(ObstacleScenes, ClothOnSphereTouchesFirstWhenTheClosedFormSays) {
  const Scene s = io::load_scene(scene_path("cloth_on_sphere.json"));
  Simulation sim(s);
  sim.set_log_contacts(true);
  // The middle particle (row 7, column 7) starts 0.2 m over the sphere's top. In free fall with
  // linear drag c on an interior particle of mass m (k = c / m): h = (g / k) (t - (1 - e^{-k t}) / k).
  const int mid = 7 * 15 + 7;
  const double m = s.particles.inv_mass[mid] > 0 ? 1.0 / s.particles.inv_mass[mid] : 0.0;
  const double g = 9.81, kd = s.forces.air_drag.value_or(0.0) / m, h = 0.2;
  double lo = 0.0, hi = 1.0;
  for (int it = 0; it < 100; ++it) {
    const double t = 0.5 * (lo + hi);
    ((g / kd) * (t - (1 - std::exp(-kd * t)) / kd) < h ? lo : hi) = t;
  }
  while (sim.contact_log().empty() && sim.steps_done() < s.steps) ASSERT_TRUE(sim.step());
  ASSERT_FALSE(sim.contact_log().empty());
  const ContactEvent& first = sim.contact_log().front();
  EXPECT_EQ(first.particle, mid);
  EXPECT_EQ(first.obstacle, 0);
  // Within two steps: the cloth's lighter border particles feel more drag and pull on the middle.
  EXPECT_NEAR(first.time, lo, 2 * s.dt) << "closed form " << lo;
  const Simulation rest = run_checked(s);
  // Draped: the middle particle rests on the sphere near its top.
  const Vec3 x = rest.particles().x[mid];
  // (Sliding along the tangent for a step leaves it about (v h)^2 / 2r above: 1e-6 m is far above that.)
  EXPECT_NEAR((x - Vec3(0, 0.3, 0)).norm(), 0.3, 1e-6);
  EXPECT_GT(x.y(), 0.599);
}

TEST(ObstacleScenes, MovingSpherePushesTheCurtainAndIsDrawnWhereItIs) {
  const Scene s = io::load_scene(scene_path("cloth_moving_sphere.json"));
  const Simulation sim = run_checked(s);
  EXPECT_GT(sim.obstacle_contacts().counters().contacts, 0);
  // Frames: the sphere's drawing moves with it, 0.5 m/s along z (frame every 500 steps = 1 s).
  const auto dir = testing::temp_dir("movingsphere");
  const auto r = testing::run_cli("run '" + scene_path("cloth_moving_sphere.json") + "' --json --out '" +
                                  (dir / "out").string() + "' --frame-every 500");
  ASSERT_EQ(r.code, 0) << r.err;
  for (int step : {0, 500, 1000}) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06d.obj", step);
    std::istringstream in(testing::slurp(dir / "out" / "frames" / name));
    std::string line;
    bool in_obstacle = false;
    double zsum = 0.0;
    int n = 0;
    while (std::getline(in, line)) {
      if (line.rfind("o obstacle_0", 0) == 0) in_obstacle = true;
      if (in_obstacle && line.rfind("v ", 0) == 0) {
        double x, y, z;
        std::sscanf(line.c_str(), "v %lf %lf %lf", &x, &y, &z);
        zsum += z;
        ++n;
      }
    }
    ASSERT_GT(n, 0) << name;
    // The drawn sphere is symmetric about its centre: its vertices' mean z is the centre's.
    EXPECT_NEAR(zsum / n, -0.6 + 0.5 * step * s.dt, 1e-6) << name;
  }
  std::filesystem::remove_all(dir);
}

TEST(ObstacleScenes, BlockAsAnObjMeshRestsTheClothOnItsTopAndKeepsItOut) {
  // The 121-particle block scene with its cube given as an OBJ mesh (eight vertices, six quads,
  // which the reader turns into fans) instead of the analytic box: the scene reads it relative
  // to its own file, runs stable, no free particle is ever strictly inside the cube (the exact
  // test of the box it encloses), and the particle over the centre rests on the top face,
  // y = 0.75, as on the analytic box.
  const auto dir = testing::temp_dir("meshblock");
  testing::write_text(dir / "block.obj", "v -0.25 0.25 -0.25\nv 0.25 0.25 -0.25\nv 0.25 0.75 -0.25\nv -0.25 0.75 -0.25\n"
                                         "v -0.25 0.25 0.25\nv 0.25 0.25 0.25\nv 0.25 0.75 0.25\nv -0.25 0.75 0.25\n"
                                         "f 1 4 3 2\nf 5 6 7 8\nf 1 5 8 4\nf 2 3 7 6\nf 1 2 6 5\nf 4 8 7 3\n");
  nlohmann::json scene = nlohmann::json::parse(testing::slurp(scene_path("seed_fig10_12_block_121.json")));
  scene["obstacles"] = nlohmann::json::parse(R"([{"mesh":{"obj":"block.obj"},"friction":0.5,"elasticity":0.1}])");
  testing::write_text(dir / "block.json", scene.dump());
  const Scene s = io::load_scene((dir / "block.json").string());
  ASSERT_EQ(s.obstacles.size(), 1u);
  ASSERT_EQ(s.obstacles[0].kind, ObstacleKind::Mesh);
  const Vec3 center(0.0, 0.5, 0.0), half(0.25, 0.25, 0.25);
  Simulation sim(s);
  for (long long k = 0; k < s.steps; ++k) {
    ASSERT_TRUE(sim.step()) << "unstable at step " << k + 1;
    for (std::size_t i = 0; i < sim.particles().x.size(); ++i)
      ASSERT_FALSE(inside_box(sim.particles().x[i] - center, half)) << "particle " << i << " inside after step " << k + 1;
  }
  EXPECT_GT(sim.obstacle_contacts().counters().contacts, 0);
  EXPECT_NEAR(sim.particles().x[60].y(), 0.75, 1e-6);
  std::filesystem::remove_all(dir);
}

TEST(ObstacleScenes, RunResultCountsEdgeContactsWhenOn) {
  // The 121-particle block with edge_contacts on, 0.5 s (it lands at about 0.23 s): the result
  // carries the spring-box counters, with contacts and nothing left unresolved.
  const auto dir = testing::temp_dir("edgecounters");
  std::string text = testing::slurp(scene_path("seed_fig10_12_block_121.json"));
  const auto pos = text.find("\"edge_contacts\": false");
  ASSERT_NE(pos, std::string::npos);
  text.replace(pos, 22, "\"edge_contacts\": true");
  testing::write_text(dir / "block.json", text);
  const auto r = testing::run_cli("run '" + (dir / "block.json").string() + "' --json --steps 250");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("edge_contacts")) << r.out.substr(0, 200);
  EXPECT_GT(j["edge_contacts"]["spring_box"]["contacts"].get<long long>(), 0);
  EXPECT_EQ(j["edge_contacts"]["spring_box"]["unresolved"].get<long long>(), 0);
  const auto off = testing::run_cli("run '" + scene_path("seed_fig10_12_block_121.json") + "' --json --steps 10");
  ASSERT_EQ(off.code, 0) << off.err;
  EXPECT_FALSE(nlohmann::json::parse(off.out).contains("edge_contacts"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido
