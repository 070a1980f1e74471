// The scene's "obstacles" block (comparisons/io/obstacle_json.*): what a good block reads into,
// and bad input (zero or negative radius, negative half extents, a missing or unreadable OBJ, a
// degenerate face, frames with another vertex count or times not increasing): the reader's
// message names the file, the JSON pointer (or the OBJ's line) and the problem; `tecido run`
// exits 2 with that one line and writes nothing.
#include "tests/support/cli_runner.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/scene_json.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace tecido {
namespace {

namespace fs = std::filesystem;

const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

std::string scene_with(const std::string& obstacles) {
  return R"({"dt":0.01,"steps":3,"gravity":[0,0,-9.81],)"
         R"("particles":[{"position":[0.2,0.2,1],"mass":1,"elasticity":0.5}],"obstacles":)" +
         obstacles + "}";
}

class ObstacleJson : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::temp_dir("obstacles");
    testing::write_text(dir_ / "tri.obj", kTriangle);
    testing::write_text(dir_ / "quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write_scene(const std::string& name, const std::string& text) {
    const std::string p = (dir_ / name).string();
    testing::write_text(p, text);
    return p;
  }
  /// Loads the scene expecting io::InputError; checks its file, location and problem, then that
  /// `tecido run --out` exits 2 with exactly that line and writes nothing.
  void expect_rejected(const std::string& text, const std::string& file, const std::string& where,
                       const std::string& problem) {
    const std::string scene = write_scene("s" + std::to_string(count_++) + ".json", text);
    const std::string expected_file = file.empty() ? scene : (dir_ / file).string();
    try {
      io::load_scene(scene);
      ADD_FAILURE() << text << ": accepted";
    } catch (const io::InputError& e) {
      EXPECT_EQ(e.file(), expected_file) << e.what();
      EXPECT_EQ(e.where(), where) << e.what();
      EXPECT_NE(e.problem().find(problem), std::string::npos) << e.what();
    }
    const fs::path out = dir_ / "out";
    const auto r = testing::run_cli("run '" + scene + "' --json --out '" + out.string() + "'");
    EXPECT_EQ(r.code, 2) << text;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err.rfind("tecido: " + expected_file + ": " + where + ": ", 0), 0u) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
    EXPECT_FALSE(fs::exists(out)) << "nothing written";
  }
  fs::path dir_;
  int count_ = 0;
};

TEST_F(ObstacleJson, ReadsEachKindWithItsMotionAndDefaults) {
  const Scene s = io::load_scene(write_scene(
      "good.json",
      scene_with(R"([{"sphere":{"center":[0,0,0],"radius":0.5},"velocity":[1,0,0]},)"
                 R"({"box":{"center":[3,0,0],"half_extents":[0.1,0.2,0.3]},"friction":0.4,"elasticity":0.7,)"
                 R"("angular_velocity":[0,0,2]},)"
                 R"({"mesh":{"obj":"quad.obj"},"frames":[{"time":0,"obj":"quad.obj"},{"time":1,"obj":"quad.obj"}]}])")));
  ASSERT_EQ(s.obstacles.size(), 3u);
  EXPECT_EQ(s.obstacles[0].kind, ObstacleKind::Sphere);
  EXPECT_EQ(s.obstacles[0].radius, 0.5);
  EXPECT_EQ(s.obstacles[0].velocity, Vec3(1, 0, 0));
  EXPECT_EQ(s.obstacles[0].friction, 0.0);          // default: frictionless
  EXPECT_FALSE(s.obstacles[0].elasticity.has_value());  // default: each particle's own k
  EXPECT_EQ(s.obstacles[1].kind, ObstacleKind::Box);
  EXPECT_EQ(s.obstacles[1].half_extents, Vec3(0.1, 0.2, 0.3));
  EXPECT_EQ(s.obstacles[1].friction, 0.4);
  EXPECT_EQ(*s.obstacles[1].elasticity, 0.7);
  EXPECT_EQ(s.obstacles[1].angular_velocity, Vec3(0, 0, 2));
  EXPECT_EQ(s.obstacles[2].kind, ObstacleKind::Mesh);
  EXPECT_EQ(s.obstacles[2].triangles.size(), 2u);  // the quad's fan
  EXPECT_EQ(s.obstacles[2].frames.size(), 2u);
  EXPECT_EQ(s.obstacles[2].center, Vec3(0.5, 0.5, 0));  // the vertices' centroid
  EXPECT_FALSE(s.edge_contacts);
}

TEST_F(ObstacleJson, RadiusMustBePositive) {
  expect_rejected(scene_with(R"([{"sphere":{"center":[0,0,0],"radius":0}}])"), "", "/obstacles/0/sphere/radius",
                  "radius must be > 0");
  expect_rejected(scene_with(R"([{"box":{"center":[5,5,5],"half_extents":[1,1,1]}},)"
                             R"({"sphere":{"center":[0,0,0],"radius":-0.5}}])"),
                  "", "/obstacles/1/sphere/radius", "radius must be > 0");
}

TEST_F(ObstacleJson, HalfExtentsMustBePositive) {
  expect_rejected(scene_with(R"([{"box":{"center":[0,0,0],"half_extents":[0.1,-0.2,0.1]}}])"), "",
                  "/obstacles/0/box/half_extents/1", "half extent must be > 0");
  expect_rejected(scene_with(R"([{"box":{"center":[0,0,0],"half_extents":[0.1,0.2,0]}}])"), "",
                  "/obstacles/0/box/half_extents/2", "half extent must be > 0");
}

TEST_F(ObstacleJson, MissingOrUnreadableObj) {
  expect_rejected(scene_with(R"([{"mesh":{"obj":"nowhere.obj"}}])"), "", "/obstacles/0/mesh/obj", "cannot read");
  fs::create_directories(dir_ / "folder.obj");
  expect_rejected(scene_with(R"([{"mesh":{"obj":"folder.obj"}}])"), "", "/obstacles/0/mesh/obj", "cannot read");
  // A bad line is reported against the OBJ file and its line.
  testing::write_text(dir_ / "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 zero\nf 1 2 3\n");
  expect_rejected(scene_with(R"([{"mesh":{"obj":"bad.obj"}}])"), "bad.obj", "line 3", "");
  testing::write_text(dir_ / "nofaces.obj", "v 0 0 0\nv 1 0 0\n");
  expect_rejected(scene_with(R"([{"mesh":{"obj":"nofaces.obj"}}])"), "nofaces.obj", "line 2", "no face");
}

TEST_F(ObstacleJson, DegenerateFaceNamesItsLine) {
  // Collinear corners (decided exactly: 0.1, 0.2, 0.3 are not exactly collinear in binary, these are).
  testing::write_text(dir_ / "flat.obj", kTriangle + std::string("v 2 2 2\nv 4 4 4\n# a comment\nf 1 4 5\n"));
  expect_rejected(scene_with(R"([{"mesh":{"obj":"flat.obj"}}])"), "flat.obj", "line 8", "degenerate face");
  testing::write_text(dir_ / "repeat.obj", kTriangle + std::string("f 1 2 2\n"));
  expect_rejected(scene_with(R"([{"mesh":{"obj":"repeat.obj"}}])"), "repeat.obj", "line 5", "degenerate face");
}

// A mesh's vertices are positions like any other: beyond the scene's coordinate limit (1e12 m) the
// file is rejected at the vertex (fuzz_obstacles' regress_mesh_beyond_coordinate_limit: 3e16 m was
// accepted, and coordinates near 1e308 summed to an infinite centre).
TEST_F(ObstacleJson, MeshVerticesMeetTheCoordinateLimit) {
  testing::write_text(dir_ / "far.obj", "v 0 0 0\nv 1 0 0\nv 0 3e16 0\nf 1 2 3\n");
  expect_rejected(scene_with(R"([{"mesh":{"obj":"far.obj"}}])"), "far.obj", "vertex 3", "out of range (|x| <= 1e+12)");
  testing::write_text(dir_ / "huge.obj", "v 1e308 0 0\nv 1.7e308 0 0\nv 1e308 1 0\nf 1 2 3\n");
  expect_rejected(scene_with(R"([{"mesh":{"obj":"huge.obj"}}])"), "huge.obj", "vertex 1", "out of range");
  // At the limit itself: accepted, its centre the vertices' mean.
  testing::write_text(dir_ / "edge.obj", "v 0 0 0\nv 1e12 0 0\nv 0 -1e12 0\nf 1 2 3\n");
  const Scene s = io::load_scene(write_scene("edge.json", scene_with(R"([{"mesh":{"obj":"edge.obj"}}])")));
  ASSERT_EQ(s.obstacles.size(), 1u);
  EXPECT_EQ(s.obstacles[0].center, Vec3(1e12 / 3, -1e12 / 3, 0));
}

TEST_F(ObstacleJson, FramesNeedOneVertexCountAndIncreasingTimes) {
  expect_rejected(scene_with(R"([{"mesh":{"obj":"tri.obj"},"frames":[{"time":0,"obj":"tri.obj"},)"
                             R"({"time":1,"obj":"quad.obj"}]}])"),
                  "", "/obstacles/0/frames/1/obj", "the frame has 4 vertices, the mesh 3");
  expect_rejected(scene_with(R"([{"mesh":{"obj":"tri.obj"},"frames":[{"time":0,"obj":"tri.obj"},)"
                             R"({"time":0,"obj":"tri.obj"}]}])"),
                  "", "/obstacles/0/frames/1/time", "must increase strictly");
  expect_rejected(scene_with(R"([{"mesh":{"obj":"tri.obj"},"frames":[{"time":1,"obj":"tri.obj"},)"
                             R"({"time":0.5,"obj":"tri.obj"}]}])"),
                  "", "/obstacles/0/frames/1/time", "must increase strictly");
  expect_rejected(scene_with(R"([{"sphere":{"center":[0,0,0],"radius":0.1},"frames":[]}])"), "",
                  "/obstacles/0/frames", "frames move a mesh only");
}

TEST_F(ObstacleJson, OtherMistakes) {
  expect_rejected(scene_with(R"([{"sphere":{"center":[0,0,0],"radius":1},"box":{"center":[0,0,0],"half_extents":[1,1,1]}}])"),
                  "", "/obstacles/0", "exactly one of");
  // A free particle starting inside a solid obstacle (the particle is at (0.2, 0.2, 1)).
  expect_rejected(scene_with(R"([{"sphere":{"center":[0,0,1],"radius":0.5}}])"), "", "/obstacles/0",
                  "free particle 0 starts inside the sphere");
  expect_rejected(scene_with(R"([{"sphere":{"center":[0,0,0],"radius":0.1},"elasticity":1.5}])"), "",
                  "/obstacles/0/elasticity", "");
  // Without an obstacle elasticity, a free particle needs its own k.
  expect_rejected(R"({"dt":0.01,"steps":1,"particles":[{"position":[0,0,1],"mass":1}],)"
                  R"("obstacles":[{"sphere":{"center":[0,0,0],"radius":0.1}}]})",
                  "", "/particles/0/elasticity", "missing required key");
}

}  // namespace
}  // namespace tecido
