// `tecido selfcollide --mesh START.obj --to END.obj`: continuous self-collision between two frames
// on a hand-worked mesh, and its bad input (exit 2).
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace tecido {
namespace {

using testing::run_cli;
using testing::temp_dir;
using testing::write_text;
using Json = nlohmann::json;

// Triangle 0 = vertices 0, 1, 2: (0,0,0), (1,0,0), (0,1,0), at rest. Triangle 1 = vertices 3, 4, 5,
// small, above it: (0.2,0.2,1), (0.3,0.2,1.25), (0.2,0.3,1.25), falling by 2.5 with a slight drift
// (0.0625, 0.03125): each of its vertices passes through triangle 0's interior (at x + y <= 0.7),
// so the vertex-face contacts are (3,0), (4,0), (5,0). Its edges stay inside triangle 0's outline
// while they cross its plane, so no edge meets an edge of triangle 0; triangle 0's vertices never
// reach triangle 1. Hand-worked answer: vertex_face [[3,0],[4,0],[5,0]], edge_edge [].
std::string frame(double dz, double dx, double dy) {
  auto v = [&](double x, double y, double z) {
    return "v " + std::to_string(x + dx) + " " + std::to_string(y + dy) + " " + std::to_string(z + dz) + "\n";
  };
  return "v 0 0 0\nv 1 0 0\nv 0 1 0\n" + v(0.2, 0.2, 1) + v(0.3, 0.2, 1.25) + v(0.2, 0.3, 1.25) + "f 1 2 3\nf 4 5 6\n";
}

TEST(CliSelfCollideContinuous, EveryEngineFindsTheHandWorkedContacts) {
  const auto dir = temp_dir("sc-to");
  write_text(dir / "a.obj", frame(0, 0, 0));
  write_text(dir / "b.obj", frame(-2.5, 0.0625, 0.03125));
  const auto r = run_cli("selfcollide --mesh '" + (dir / "a.obj").string() + "' --to '" + (dir / "b.obj").string() +
                         "' --engines core,core-brute,exact --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const Json out = Json::parse(r.out);
  const Json expected = Json::parse(R"({"vertex_face":[[3,0],[4,0],[5,0]],"edge_edge":[]})");
  for (const char* e : {"core", "core-brute", "exact"}) EXPECT_EQ(out.at(e), expected) << e << ": " << r.out;
  // Moving the other way (b to a) is the same motion reversed: the same contacts.
  const auto back = run_cli("selfcollide --mesh '" + (dir / "b.obj").string() + "' --to '" + (dir / "a.obj").string() +
                            "' --engines exact --json");
  ASSERT_EQ(back.code, 0) << back.err;
  EXPECT_EQ(Json::parse(back.out).at("exact"), expected);
  // A small motion that stays above: nothing.
  write_text(dir / "c.obj", frame(-0.5, 0, 0));
  const auto none = run_cli("selfcollide --mesh '" + (dir / "a.obj").string() + "' --to '" + (dir / "c.obj").string() + "' --json");
  ASSERT_EQ(none.code, 0) << none.err;
  EXPECT_EQ(Json::parse(none.out), Json::parse(R"({"core":{"vertex_face":[],"edge_edge":[]}})"));
}

// A 48 x 48 grid of spacing 1/32 (4418 triangles) whose vertices move by up to 3/64 in each
// direction (a pseudo-random pattern in multiples of 1/512, exact in decimal): thousands of
// crossings, tens of thousands of tree pairs, enough for the detector to run in shares.
std::string wavy_grid(bool moved) {
  const int n = 48;
  std::string obj;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      const int h = (r * 7919 + c * 104729) % 49 - 24;  // -24 .. 24
      const double d = moved ? h / 512.0 : 0.0;
      obj += "v " + std::to_string(c / 32.0 + d) + " " + std::to_string(r / 32.0 - d) + " " +
             std::to_string(moved ? ((r + c) % 3 - 1) * d : 0.0) + "\n";
    }
  for (int r = 0; r + 1 < n; ++r)
    for (int c = 0; c + 1 < n; ++c) {
      const int a = r * n + c + 1;
      obj += "f " + std::to_string(a) + " " + std::to_string(a + 1) + " " + std::to_string(a + n + 1) + "\n";
      obj += "f " + std::to_string(a) + " " + std::to_string(a + n + 1) + " " + std::to_string(a + n) + "\n";
    }
  return obj;
}

TEST(CliSelfCollideContinuous, SameBytesAtEveryThreadCount) {
  const auto dir = temp_dir("sc-to-threads");
  write_text(dir / "a.obj", wavy_grid(false));
  write_text(dir / "b.obj", wavy_grid(true));
  const std::string args = "selfcollide --mesh '" + (dir / "a.obj").string() + "' --to '" + (dir / "b.obj").string() + "' --json";
  const auto one = run_cli(args + " --threads 1");
  ASSERT_EQ(one.code, 0) << one.err;
  const Json c = Json::parse(one.out).at("core");
  EXPECT_GT(c.at("vertex_face").size() + c.at("edge_edge").size(), 100u);
  for (const char* t : {"2", "3", "0"}) {
    const auto r = run_cli(args + " --threads " + t);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out, one.out) << "--threads " << t;
  }
  const auto bad = run_cli(args + " --threads -1");
  EXPECT_EQ(bad.code, 2);
  EXPECT_EQ(bad.out, "");
  EXPECT_NE(bad.err.find("--threads"), std::string::npos) << bad.err;
}

TEST(CliSelfCollideContinuous, DifferentMeshesExitTwoNamingTheFiles) {
  const auto dir = temp_dir("sc-to-bad");
  const std::string d = dir.string();
  write_text(dir / "a.obj", frame(0, 0, 0));
  write_text(dir / "more.obj", frame(0, 0, 0) + "v 5 5 5\n");
  write_text(dir / "faces.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0.2 0.2 1\nv 0.3 0.2 1.25\nv 0.2 0.3 1.25\nf 1 2 3\nf 4 6 5\n");
  std::string big;  // 2 x 1100 triangles: over the exact engine's limit
  for (int k = 0; k < 2300; ++k) big += "v " + std::to_string(k) + " 0 " + std::to_string(k % 2) + "\n";
  for (int k = 1; k + 2 <= 2300; ++k) big += "f " + std::to_string(k) + " " + std::to_string(k + 1) + " " + std::to_string(k + 2) + "\n";
  write_text(dir / "big.obj", big);
  write_text(dir / "nan.obj", "v x 0 0\n");
  struct Case {
    std::string args, message;
  };
  const std::vector<Case> cases = {
      {"--mesh '" + d + "/a.obj' --to '" + d + "/more.obj'", "--to " + d + "/more.obj: 7 vertices, but --mesh " + d + "/a.obj has 6"},
      {"--mesh '" + d + "/a.obj' --to '" + d + "/faces.obj'", d + "/faces.obj: line 8: triangle 1 differs from " + d + "/a.obj's (line 8)"},
      {"--mesh '" + d + "/big.obj' --to '" + d + "/big.obj' --engines exact", "exact tests every pair and takes at most 2048 triangles"},
      {"--mesh '" + d + "/a.obj' --to '" + d + "/a.obj' --engines fcl", "unknown continuous self-collision engine \"fcl\""},
      {"--mesh '" + d + "/a.obj' --to '" + d + "/missing.obj'", d + "/missing.obj"},
      // Read side by side on two threads, the frames' errors are still reported as in turn:
      // the start frame's when both have one.
      {"--mesh '" + d + "/nan.obj' --to '" + d + "/missing.obj' --threads 2", d + "/nan.obj: line 1: \"x\" is not a number"},
      {"--mesh '" + d + "/a.obj' --to '" + d + "/nan.obj' --threads 2", d + "/nan.obj: line 1: \"x\" is not a number"},
  };
  for (const Case& c : cases) {
    const auto r = run_cli("selfcollide " + c.args + " --json");
    EXPECT_EQ(r.code, 2) << c.args;
    EXPECT_EQ(r.out, "") << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
  }
}

}  // namespace
}  // namespace tecido
