// `tecido run --out DIR`: the frames (OBJ, VTK) and the key-frame picture, the self_collision
// scene key and its result block, and the unchanged JSON contract.
#include "tests/support/cli_runner.h"
#include "comparisons/io/frame_writer.h"
#include "comparisons/io/gnuplot.h"
#include "comparisons/io/obstacle_surfaces.h"
#include "comparisons/io/scene_json.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <sstream>

namespace tecido {
namespace {

using testing::run_cli;

const char* kCloth = R"({"_note":"a small curtain in a circling wind",
 "dt":0.01,"steps":120,"gravity":[0,-9.81,0],"air_drag":0.02,
 "wind":{"force":[0.1,0,0],"swirl":{"rate":1.0,"axis":[0,1,0],"phase":0}},
 "cloth":{"rows":6,"cols":5,"spacing":0.1,"origin":[0,1,0],"axis_u":[0,0,1],"axis_v":[0,-1,0],
          "total_mass":0.3,"stiffness_b":4,"stiffness_a":4,"pins":[[0,0],[0,4]]},
 "self_collision":{"response":"gia+edge3","strength":0.05,"every":2}})";

int count_lines(const std::string& text, const std::string& prefix) {
  std::istringstream in(text);
  std::string line;
  int n = 0;
  while (std::getline(in, line)) n += line.rfind(prefix, 0) == 0;
  return n;
}

TEST(CliRunFrames, WritesFramesPictureAndSelfCollisionBlock) {
  const auto dir = testing::temp_dir("frames");
  const std::string scene = (dir / "cloth.json").string();
  testing::write_text(scene, kCloth);
  const auto r = run_cli("run '" + scene + "' --json --out '" + (dir / "out").string() + "' --frame-every 50 --vtk");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "ok");
  EXPECT_EQ(j["steps"], 120);
  ASSERT_EQ(j["particles"].size(), 30u);
  ASSERT_TRUE(j.contains("self_collision"));
  EXPECT_EQ(j["self_collision"]["response"], "gia+edge3");
  EXPECT_EQ(j["self_collision"]["checks"], 60);  // every 2nd of 120 steps
  // Frames 0, 50, 100 and the last (120), as OBJ and VTK.
  for (int step : {0, 50, 100, 120}) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06d", step);
    const std::string obj = testing::slurp(dir / "out" / "frames" / (std::string(name) + ".obj"));
    EXPECT_EQ(count_lines(obj, "v "), 30) << name;
    EXPECT_EQ(count_lines(obj, "f "), 2 * 5 * 4) << name;
    const std::string vtk = testing::slurp(dir / "out" / "frames" / (std::string(name) + ".vtk"));
    EXPECT_EQ(vtk.rfind("# vtk DataFile Version 3.0\n", 0), 0u) << name;
    EXPECT_NE(vtk.find("POINTS 30 double"), std::string::npos);
    EXPECT_NE(vtk.find("POLYGONS 40 160"), std::string::npos);
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "frames" / "frame_000001.obj"));
  // The last frame's vertices are the final particle positions (9 significant digits).
  {
    std::istringstream in(testing::slurp(dir / "out" / "frames" / "frame_000120.obj"));
    std::string tag, line;
    std::getline(in, line);  // comment
    for (int i = 0; i < 30; ++i) {
      double x, y, z;
      in >> tag >> x >> y >> z;
      EXPECT_NEAR(x, j["particles"][i]["x"][0].get<double>(), 1e-8);
      EXPECT_NEAR(y, j["particles"][i]["x"][1].get<double>(), 1e-8);
      EXPECT_NEAR(z, j["particles"][i]["x"][2].get<double>(), 1e-8);
    }
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "cloth.gp"));
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "cloth.dat"));
  if (io::gnuplot_available()) {
    const std::string svg = testing::slurp(dir / "out" / "cloth.svg");
    EXPECT_NE(svg.find("<svg"), std::string::npos);
  } else {
    EXPECT_NE(r.err.find("gnuplot not found"), std::string::npos) << r.err;
  }
  const auto written = nlohmann::json::parse(testing::slurp(dir / "out" / "result.json"));
  EXPECT_EQ(written["particles"], j["particles"]);
  EXPECT_EQ(written["self_collision"], j["self_collision"]);
  std::filesystem::remove_all(dir);
}

// A second run into the same --out: the first run's frames are gone (with a note), the second's
// are all there, and files that are not tecido's frames survive.
TEST(CliRunFrames, AnEarlierRunsFramesAreRemovedAndNothingElse) {
  const auto dir = testing::temp_dir("stale");
  const std::string scene = (dir / "cloth.json").string();
  testing::write_text(scene, kCloth);
  const auto out = dir / "out";
  const auto first = run_cli("run '" + scene + "' --json --out '" + out.string() + "' --frame-every 10 --vtk");
  ASSERT_EQ(first.code, 0) << first.err;
  EXPECT_EQ(first.err.find("earlier run"), std::string::npos) << first.err;
  testing::write_text(out / "frames" / "notes.txt", "mine");
  testing::write_text(out / "frames" / "frame_12.obj", "not tecido's name");
  const auto second = run_cli("run '" + scene + "' --json --out '" + out.string() + "' --frame-every 50");
  ASSERT_EQ(second.code, 0) << second.err;
  // 13 frames (0, 10, ..., 120) as OBJ and VTK.
  EXPECT_NE(second.err.find("tecido: note: removed 26 frame files of an earlier run from " + out.string() + "/frames\n"),
            std::string::npos)
      << second.err;
  std::set<std::string> left;
  for (const auto& e : std::filesystem::directory_iterator(out / "frames")) left.insert(e.path().filename().string());
  EXPECT_EQ(left, (std::set<std::string>{"frame_000000.obj", "frame_000050.obj", "frame_000100.obj", "frame_000120.obj",
                                         "notes.txt", "frame_12.obj"}));
  EXPECT_EQ(testing::slurp(out / "frames" / "notes.txt"), "mine");
  std::filesystem::remove_all(dir);
}

TEST(CliRunFrames, WithoutOutNothingIsWrittenAndTheResultIsTheSame) {
  const auto dir = testing::temp_dir("noframes");
  const std::string scene = (dir / "cloth.json").string();
  testing::write_text(scene, kCloth);
  const auto a = run_cli("run '" + scene + "' --json");
  const auto b = run_cli("run '" + scene + "' --json --out '" + (dir / "out").string() + "' --frame-every 7");
  ASSERT_EQ(a.code, 0);
  ASSERT_EQ(b.code, 0);
  EXPECT_EQ(a.out, b.out);  // writing frames does not change the run
  std::size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 1u);  // only the scene in the directory itself
  std::filesystem::remove_all(dir);
}

TEST(FrameWriter, PointCloudWithoutTriangles) {
  const std::vector<Vec3> x = {Vec3(0, 0, 0), Vec3(1, 2, 3)};
  const std::string obj = io::obj_frame_text(x, {}, "two points");
  EXPECT_EQ(obj, "# two points\nv 0 0 0\nv 1 2 3\n");
  const std::string vtk = io::vtk_frame_text(x, {}, {}, "t");
  EXPECT_NE(vtk.find("VERTICES 2 4\n1 0\n1 1\n"), std::string::npos);
  EXPECT_EQ(vtk.find("POINT_DATA"), std::string::npos);
}

TEST(FrameWriter, ObstaclesFollowTheParticlesAsTheirOwnObjectsAndCells) {
  const std::vector<Vec3> x = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  const std::vector<std::array<int, 3>> cloth = {{0, 1, 2}};
  io::SurfaceMesh tri;
  tri.vertices = {Vec3(0, 0, -1), Vec3(2, 0, -1), Vec3(0, 2, -1)};
  tri.triangles = {{0, 2, 1}};
  const std::string obj = io::obj_frame_text(x, cloth, "c", {tri});
  EXPECT_EQ(obj,
            "# c\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
            "o obstacle_0\nv 0 0 -1\nv 2 0 -1\nv 0 2 -1\nf 4 6 5\n");
  const std::string vtk = io::vtk_frame_text(x, x, cloth, "t", {tri});
  EXPECT_NE(vtk.find("POINTS 6 double\n"), std::string::npos);
  EXPECT_NE(vtk.find("POLYGONS 2 8\n3 0 1 2\n3 3 5 4\n"), std::string::npos);
  EXPECT_NE(vtk.find("POINT_DATA 6\n"), std::string::npos);
  EXPECT_NE(vtk.find("0 0 0\n0 0 0\n0 0 0\nCELL_DATA 2\nSCALARS body int 1\nLOOKUP_TABLE default\n0\n1\n"),
            std::string::npos);
}

TEST(ObstacleSurfaces, BoxAndMovingSphereAtTheirPoses) {
  Obstacle box;
  box.kind = ObstacleKind::Box;
  box.center = Vec3(1, 2, 3);
  box.half_extents = Vec3(0.5, 0.25, 0.125);
  box.velocity = Vec3(1, 0, 0);
  Obstacle ball;
  ball.kind = ObstacleKind::Sphere;
  ball.radius = 0.5;
  ball.velocity = Vec3(0, 0, 2);
  const auto s = io::obstacle_surfaces({box, ball}, 0.5);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].vertices.size(), 8u);
  EXPECT_EQ(s[0].triangles.size(), 12u);
  for (const Vec3& v : s[0].vertices) {  // every corner at (1.5, 2, 3) + (+-0.5, +-0.25, +-0.125)
    EXPECT_NEAR(std::abs(v.x() - 1.5), 0.5, 1e-12);
    EXPECT_NEAR(std::abs(v.y() - 2.0), 0.25, 1e-12);
    EXPECT_NEAR(std::abs(v.z() - 3.0), 0.125, 1e-12);
  }
  for (const Vec3& v : s[1].vertices) EXPECT_NEAR((v - Vec3(0, 0, 1)).norm(), 0.5, 1e-12);
}

struct BadKey {
  std::string patch;
  const char* where;
  const char* problem;
};

TEST(SceneSelfCollision, BadValuesNameTheJsonPath) {
  const std::string good = kCloth;
  const auto with = [&](const std::string& sc) {
    std::string s = good;
    const auto pos = s.find(R"("self_collision":{)");
    const auto end = s.find('}', pos);
    s.replace(pos, end - pos + 1, sc);
    return s;
  };
  const BadKey cases[] = {
      {with(R"("self_collision":{"response":"sideways","strength":1})"), "/self_collision/response", "unknown response"},
      {with(R"("self_collision":{"response":"edge3"})"), "/self_collision/strength", "missing"},
      {with(R"("self_collision":{"response":"edge3","strength":-1})"), "/self_collision/strength", ""},
      {with(R"("self_collision":{"response":"none","every":0})"), "/self_collision/every", ""},
      {with(R"("self_collision":{"response":"none","evry":2})"), "/self_collision", "evry"},
      {R"({"dt":0.01,"steps":1,"particles":[{"position":[0,0,0],"mass":1}],"self_collision":{"response":"none"}})",
       "/self_collision", "needs a cloth"},
  };
  const auto dir = testing::temp_dir("badsc");
  int k = 0;
  for (const BadKey& c : cases) {
    const std::string file = (dir / ("s" + std::to_string(k++) + ".json")).string();
    testing::write_text(file, c.patch);
    const auto r = run_cli("run '" + file + "' --json");
    EXPECT_EQ(r.code, 2) << c.patch;
    EXPECT_NE(r.err.find(file + ": " + c.where), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.problem), std::string::npos) << r.err;
  }
  // And the good one loads with its settings.
  const Scene s = io::scene_from_json(io::parse_json_text(good, "good.json"), "good.json");
  ASSERT_TRUE(s.self_collision);
  EXPECT_EQ(s.self_collision->response, SelfCollisionResponse::GiaEdge3);
  EXPECT_EQ(s.self_collision->strength, 0.05);
  EXPECT_EQ(s.self_collision->every, 2);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido
