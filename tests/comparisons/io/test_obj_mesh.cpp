// The OBJ reader (comparisons/io/obj_mesh.h) and `tecido selfcollide`: faces in all index
// forms, quads split as documented, bad files exit 2 naming the file and the line.
#include "tests/support/cli_runner.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/obj_mesh.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

namespace tecido {
namespace {

using testing::run_cli;

TEST(ObjMesh, ParsesIndexFormsNegativeIndicesAndSplitsQuads) {
  const io::ObjMesh m = io::parse_obj_text(
      "# comment\n"
      "o thing\nv 0 0 0\nv 1 0 0 1.0\nv 1 1 0\nv 0 1 0   # trailing comment\n"
      "vt 0 0\nvn 0 0 1\ns off\n\n"
      "f 1 2 3\n"
      "f 1/1 3/1/1 4//1\n"
      "f -4 -3 -2 -1\n"
      "f 1 2 3 4 5\n"
      "v 0.5 0.5 1\n",
      "m.obj");
  ASSERT_EQ(m.vertices.size(), 5u);
  EXPECT_EQ(m.vertices[1], Vec3(1, 0, 0));
  const std::vector<std::array<int, 3>> expected = {
      {0, 1, 2}, {0, 2, 3},             // f 1 2 3; f 1/1 3/1/1 4//1
      {0, 1, 2}, {0, 2, 3},             // the quad -4 -3 -2 -1 = 1 2 3 4 -> (1,2,3), (1,3,4)
      {0, 1, 2}, {0, 2, 3}, {0, 3, 4}}; // the pentagon's fan; vertex 5 is defined after it
  EXPECT_EQ(m.triangles, expected);
  EXPECT_EQ(m.triangle_line, (std::vector<int>{11, 12, 13, 13, 14, 14, 14}));
}

TEST(ObjMesh, EveryNumberFormReadsAsStrtodReadsIt) {
  // Plain numbers take the fast reader (std::from_chars); a sign '+', hex, a subnormal and an
  // underflow to zero the strtod path: each must give strtod's double (worked values).
  const io::ObjMesh m = io::parse_obj_text(
      "v +1 -0.5 .25\n"
      "v 0x1p-3 1e-310 1e-400\n"
      "v 0.1 3.0000000000000004 1E2\n"
      "f +1 2 -1\n",
      "forms.obj");
  ASSERT_EQ(m.vertices.size(), 3u);
  EXPECT_EQ(m.vertices[0], Vec3(1, -0.5, 0.25));
  EXPECT_EQ(m.vertices[1][0], 0.125);
  EXPECT_EQ(m.vertices[1][1], std::strtod("1e-310", nullptr));
  EXPECT_GT(m.vertices[1][1], 0.0) << "a subnormal, not flushed";
  EXPECT_EQ(m.vertices[1][2], 0.0);
  EXPECT_EQ(m.vertices[2][0], 0.1);
  EXPECT_EQ(m.vertices[2][1], 3.0000000000000004);
  EXPECT_NE(m.vertices[2][1], 3.0);
  EXPECT_EQ(m.vertices[2][2], 100.0);
  EXPECT_EQ(m.triangles, (std::vector<std::array<int, 3>>{{0, 1, 2}}));
}

struct BadObj {
  const char* name;
  const char* text;
  int line;
  const char* problem;
};

TEST(ObjMesh, BadFilesExitTwoWithFileAndLine) {
  const BadObj cases[] = {
      {"missing_vertex", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", 4, "missing vertex 4"},
      {"negative_missing", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n", 3, "missing vertex"},
      {"zero_index", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", 4, "index 0"},
      {"repeated", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 1\n", 4, "degenerate face"},
      {"repeated_by_sign", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -3\n", 4, "degenerate face"},
      {"two_corners", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", 4, "at least three"},
      {"nan", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n", 2, "not finite"},
      {"inf", "v 0 0 0\nv 1 0 1e999\nv 0 1 0\nf 1 2 3\n", 2, "not finite"},
      {"not_a_number", "v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n", 2, "not a number"},
      {"short_vertex", "v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", 1, "three coordinates"},
      {"bad_index", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n", 4, "not a vertex index"},
      {"no_face", "v 0 0 0\nv 1 0 0\n", 2, "no face"},
  };
  const auto dir = testing::temp_dir("obj");
  for (const BadObj& c : cases) {
    const std::string file = (dir / (std::string(c.name) + ".obj")).string();
    testing::write_text(file, c.text);
    const auto r = run_cli("selfcollide --mesh '" + file + "' --json");
    EXPECT_EQ(r.code, 2) << c.name;
    EXPECT_TRUE(r.out.empty()) << c.name;
    EXPECT_NE(r.err.find(file + ": line " + std::to_string(c.line) + ": "), std::string::npos) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(c.problem), std::string::npos) << c.name << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.name;
  }
  const auto missing = run_cli("selfcollide --mesh '" + (dir / "nope.obj").string() + "' --json");
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("no such file"), std::string::npos);
  const auto engine = run_cli("selfcollide --mesh '" + (dir / "nan.obj").string() + "' --engines core,nope --json");
  EXPECT_EQ(engine.code, 2);
  EXPECT_NE(engine.err.find("unknown self-collision engine \"nope\""), std::string::npos) << engine.err;
  std::filesystem::remove_all(dir);
}

// A crumpled strip written as OBJ (quads): core and core-brute agree, pairs are i < j, sorted,
// never sharing a vertex, numbered in the file's triangle order.
TEST(CliSelfCollide, EnginesAgreeOnACrumpledMesh) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> jitter(-0.35, 0.35);
  const int rows = 8, cols = 12;
  std::string obj = "# crumpled strip\n";
  std::vector<Vec3> x;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      // A grid 0.2 apart, crumpled by noise of the same size: non-neighbours cross.
      x.emplace_back(c * 0.2 + 0.5 * jitter(rng), r * 0.2 + 0.5 * jitter(rng), jitter(rng));
      obj += "v " + std::to_string(x.back().x()) + " " + std::to_string(x.back().y()) + " " + std::to_string(x.back().z()) + "\n";
    }
  for (int r = 0; r + 1 < rows; ++r)
    for (int c = 0; c + 1 < cols; ++c) {
      const int a = r * cols + c + 1;
      obj += "f " + std::to_string(a) + " " + std::to_string(a + 1) + " " + std::to_string(a + cols + 1) + " " +
             std::to_string(a + cols) + "\n";
    }
  const auto dir = testing::temp_dir("selfcollide");
  const std::string file = (dir / "strip.obj").string();
  testing::write_text(file, obj);
  const auto r = run_cli("selfcollide --mesh '" + file + "' --engines core-brute,core --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("core") && j.contains("core-brute"));
  EXPECT_EQ(j["core"], j["core-brute"]);
  ASSERT_GT(j["core"].size(), 0u);
  const io::ObjMesh m = io::load_obj_mesh(file);
  std::array<int, 2> prev{-1, -1};
  for (const auto& p : j["core"]) {
    const std::array<int, 2> q{p[0].get<int>(), p[1].get<int>()};
    EXPECT_LT(q[0], q[1]);
    EXPECT_LT(prev, q);
    prev = q;
    for (int a : m.triangles[q[0]])
      for (int b : m.triangles[q[1]]) EXPECT_NE(a, b);
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido
