// Every row of the limits table (comparisons/io/limits.h, docs/limits.md "Limits"): the command, exit 2,
// the one line naming the pointer, line or option and the limit, and nothing written. The input
// file's size and the nesting depth are in test_text_file.cpp and test_json_reader.cpp.
#include "tests/support/rejection.h"
#include "comparisons/io/limits.h"

#include <gtest/gtest.h>

namespace tecido {
namespace {

using testing::expect_rejected;
using testing::run_cli;

/// n copies of `item`, comma-separated (the readers count a list before reading its entries).
std::string list_of(std::size_t n, const std::string& item) {
  std::string s;
  s.reserve(n * (item.size() + 1));
  for (std::size_t k = 0; k < n; ++k) (s += k ? "," : "") += item;
  return s;
}

const std::string kParticle = R"({"position":[0,0,0],"mass":1})";

class Limits : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::temp_dir("limits"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string file(const std::string& name, const std::string& text) {
    testing::write_text(dir_ / name, text);
    return (dir_ / name).string();
  }
  std::string out() const { return (dir_ / "out").string(); }
  /// `tecido run FILE --out DIR` rejected with `needles`, DIR never created.
  void expect_run_rejected(const std::string& scene, const std::string& extra, std::initializer_list<std::string> needles) {
    expect_rejected(run_cli("run '" + scene + "' --out '" + out() + "' " + extra), needles, scene + " " + extra);
    EXPECT_FALSE(std::filesystem::exists(out()));
  }
  std::filesystem::path dir_;
};

TEST_F(Limits, Particles) {
  const auto n = io::kMaxParticles + 1;
  const std::string s = file("p.json", R"({"dt":0.01,"steps":1,"particles":[)" + list_of(n, "0") + "]}");
  expect_run_rejected(s, "", {s + ": /particles: 1048577 particles, more than the limit of 1048576"});
  // Listed particles and a cloth's nodes count together.
  const std::string c = file("c.json", R"({"dt":0.01,"steps":1,"particles":[)" + list_of(16, kParticle) +
                                           R"(],"cloth":{"rows":1024,"cols":1024,"spacing":0.01,"origin":[0,0,0],)"
                                           R"("axis_u":[1,0,0],"axis_v":[0,1,0],"total_mass":1,"stiffness_b":1}})");
  expect_run_rejected(c, "", {c + ": /cloth: 1048592 particles (16 listed and 1048576 of the cloth), more than the limit of 1048576"});
}

TEST_F(Limits, ClothNodes) {
  const std::string s = file("c.json", R"({"dt":0.01,"steps":1,"cloth":{"rows":2048,"cols":1024,"spacing":0.01,)"
                                       R"("origin":[0,0,0],"axis_u":[1,0,0],"axis_v":[0,1,0],"total_mass":1,"stiffness_b":1}})");
  expect_run_rejected(s, "", {s + ": /cloth/cols: rows x cols = 2097152 nodes, more than the limit of 1048576"});
  const std::string side = file("side.json", R"({"dt":0.01,"steps":1,"cloth":{"rows":2,"cols":4097,"spacing":0.01,)"
                                             R"("origin":[0,0,0],"axis_u":[1,0,0],"axis_v":[0,1,0],"total_mass":1,"stiffness_b":1}})");
  expect_run_rejected(side, "", {side + ": /cloth/cols: integer out of range [2, 4096]"});
}

// A cloth's springs and triangles are bounded by its nodes: the largest cloth fits the limits.
TEST_F(Limits, ClothSpringsAndTrianglesFitTheirLimits) {
  for (const auto& [r, c] : {std::pair<long long, long long>{1024, 1024}, {256, 4096}, {4096, 256}}) {
    ASSERT_LE(r * c, io::kMaxClothNodes);
    // Type B: horizontal, vertical, two diagonals; type A: the same two edges apart.
    const long long springs = r * (c - 1) + (r - 1) * c + 2 * (r - 1) * (c - 1) + r * (c - 2) + (r - 2) * c + 2 * (r - 2) * (c - 2);
    EXPECT_LE(springs, static_cast<long long>(io::kMaxSprings)) << r << "x" << c;
    EXPECT_LE(2 * (r - 1) * (c - 1), static_cast<long long>(io::kMaxTriangles)) << r << "x" << c;
  }
}

TEST_F(Limits, Springs) {
  const std::string s = file("s.json", R"({"dt":0.01,"steps":1,"particles":[)" + list_of(2, kParticle) + R"(],"springs":[)" +
                                           list_of(io::kMaxSprings + 1, "0") + "]}");
  expect_run_rejected(s, "", {s + ": /springs: 8388609 springs, more than the limit of 8388608"});
}

TEST_F(Limits, Planes) {
  const std::string plane = R"({"position":[0,0,0],"normal":[0,0,1],"forward":[1,0,0],"half_extents":[1,1]})";
  const std::string s = file("pl.json", R"({"dt":0.01,"steps":1,"particles":[)" + kParticle + R"(],"planes":[)" +
                                            list_of(io::kMaxPlanes + 1, plane) + "]}");
  expect_run_rejected(s, "", {s + ": /planes: 1025 planes, more than the limit of 1024"});
}

// The work of a run: steps x elements per step, checked before the first step; --max-work
// moves the limit both ways.
TEST_F(Limits, StepsAreBoundedByTheWorkLimit) {
  const std::string plane = R"({"position":[0,0,-1],"normal":[0,0,1],"forward":[1,0,0],"half_extents":[1,1]})";
  const std::string big = file("w.json", R"({"dt":0.01,"steps":1000000000,"particles":[)" +
                                             list_of(10, R"({"position":[0,0,0],"mass":1,"elasticity":0.5})") +
                                             R"(],"planes":[)" + list_of(100, plane) + "]}");
  expect_run_rejected(big, "", {big + ": /steps: 1000000000 steps x 1026 elements per step = 1.026e+12 element-steps, "
                                      "more than the work limit of 1e+11 per run (raise it with --max-work)"});
  expect_run_rejected(big, "--steps 100000000", {"--steps: 100000000 steps x 1026 elements per step"});
  // 16 + 1 particle = 17 elements per step: 10 steps are 170 element-steps.
  const std::string small = file("s.json", R"({"dt":0.01,"steps":10,"particles":[)" + kParticle + "]}");
  expect_rejected(run_cli("run '" + small + "' --max-work 169 --json"), {"/steps: 10 steps x 17 elements per step = 170"},
                  "max-work 169");
  EXPECT_EQ(run_cli("run '" + small + "' --max-work 170 --json").code, 0);
  expect_run_rejected(small, "--max-work 1e17", {"--max-work: must be <= 1e+16 (got 1e17)"});
}

TEST_F(Limits, Frames) {
  const std::string s = file("f.json", R"({"dt":0.01,"steps":200000,"particles":[)" + kParticle + "]}");
  expect_run_rejected(s, "--frame-every 1", {"--frame-every: 1 gives 200002 frames of 200000 steps, more than the limit of 100000"});
  // What the frames hold: 50001 frames of 20001 particles and triangles (a 100 x 100 cloth + 1).
  const std::string c = file("c.json", R"({"dt":0.001,"steps":100000,"particles":[)" + kParticle +
                                           R"(],"cloth":{"rows":100,"cols":100,"spacing":0.01,"origin":[0,0,0],)"
                                           R"("axis_u":[1,0,0],"axis_v":[0,1,0],"total_mass":1,"stiffness_b":1}})");
  expect_run_rejected(c, "--frame-every 2", {"--frame-every: 2 gives 50002 frames of 100000 steps of 29603 particles and triangles, "
                                              "more than the limit of 1e9 in all"});
}

TEST_F(Limits, PairsAndCases) {
  const std::string p = file("p.json", R"({"pairs":[)" + list_of(io::kMaxPairs + 1, "0") + "]}");
  expect_rejected(run_cli("tritri --pairs '" + p + "' --json"), {p + ": /pairs: 1048577 pairs, more than the limit of 1048576"},
                  "pairs");
  const std::string c = file("c.json", R"({"cases":[)" + list_of(io::kMaxCases + 1, "0") + "]}");
  expect_rejected(run_cli("plane --cases '" + c + "' --json"), {c + ": /cases: 1048577 cases, more than the limit of 1048576"},
                  "cases");
}

TEST_F(Limits, MeshVerticesAndTriangles) {
  std::string v;
  for (std::size_t k = 0; k <= io::kMaxMeshVertices; ++k) v += "v 0 0 0\n";
  const std::string mv = file("v.obj", v + "f 1 2 3\n");
  expect_rejected(run_cli("selfcollide --mesh '" + mv + "' --json"),
                  {mv + ": line 1048577: more than 1048576 vertices (the limit)"}, "vertices");
  // Faces of 1000 corners are 998 triangles each: the 2102nd face passes 2^21.
  std::string mesh;
  for (int k = 0; k < 1000; ++k) mesh += "v " + std::to_string(k) + " " + std::to_string(k % 7) + " 0\n";
  std::string face = "f";
  for (int k = 1; k <= 1000; ++k) face += " " + std::to_string(k);
  for (int k = 0; k < 2102; ++k) mesh += face + "\n";
  const std::string mt = file("t.obj", mesh);
  expect_rejected(run_cli("selfcollide --mesh '" + mt + "' --json"),
                  {mt + ": line 3102: more than 2097152 triangles (the limit; a face of n corners is n - 2)"}, "triangles");
}

TEST_F(Limits, AllPairsEnginesTakeAtMostBruteForceTriangles) {
  // A strip of kMaxBruteForceTriangles + 1 triangles.
  const std::size_t n = io::kMaxBruteForceTriangles + 1;
  std::string mesh;
  for (std::size_t k = 0; k < n + 2; ++k) mesh += "v " + std::to_string(k / 2) + " " + std::to_string(k % 2) + " 0\n";
  for (std::size_t k = 1; k <= n; ++k) mesh += "f " + std::to_string(k) + " " + std::to_string(k + 1) + " " + std::to_string(k + 2) + "\n";
  const std::string m = file("strip.obj", mesh);
  expect_rejected(run_cli("selfcollide --mesh '" + m + "' --engines core,core-brute --json"),
                  {"--engines: core-brute tests every pair of triangles and takes at most 16384, but " + m + " has 16385"},
                  "core-brute");
  EXPECT_EQ(run_cli("selfcollide --mesh '" + m + "' --engines core --json").code, 0);
}

TEST_F(Limits, ThreadsShardsAndTheExperimentsWork) {
  expect_rejected(run_cli("suite order --threads 1025 --out '" + out() + "'"), {"--threads: must be in [0, 1024] (got 1025)"},
                  "threads");
  expect_rejected(run_cli("experiment self-contact --threads -1 --out '" + out() + "'"),
                  {"--threads: must be in [0, 1024] (got -1)"}, "threads");
  expect_rejected(run_cli("suite tritri --shard 0/65537 --out '" + out() + "'"),
                  {"--shard: \"0/65537\" is not i/n with 0 <= i < n <= 65536"}, "shard");
  // Each run of the experiment fits the work limit: a quick run of the seed's scene is 400 steps
  // at the smallest dt (0.005 s).
  expect_rejected(run_cli("experiment self-contact --quick --max-work 1000 --out '" + out() + "'"),
                  {"seed_fig21_self_contact.json: /: a run of the experiment: 400 steps x ", "more than the work limit of 1000"},
                  "experiment work");
  EXPECT_FALSE(std::filesystem::exists(out()));
}

}  // namespace
}  // namespace tecido
