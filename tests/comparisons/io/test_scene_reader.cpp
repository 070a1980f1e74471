// Bad scene files: each exits 2 with one line on stderr naming the file, the JSON path and the
// problem, and nothing is written. Good scenes load as written.
#include "tests/support/cli_runner.h"
#include "comparisons/io/scene_json.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido {
namespace {

using testing::run_cli;

const char* kGood = R"({"gravity":[0,0,-9.81],"integrator":"symplectic","dt":0.01,"steps":10,
 "particles":[{"position":[0,0,1],"velocity":[0,0,0],"mass":1.0,"pinned":false,"elasticity":0.5},
              {"position":[1,0,1],"mass":2.0,"elasticity":0.5}],
 "springs":[{"i":0,"j":1,"stiffness":4.0,"rest_length":1.0}],
 "planes":[{"position":[0,0,0],"normal":[0,0,1],"forward":[1,0,0],"half_extents":[2,2],"friction":0.5}]})";

/// A 3 x 3 cloth over the origin without "elasticity" (the document is left open for more keys).
const char* kClothNoK = R"({"dt":0.01,"steps":1,"gravity":[0,0,-9.81],"cloth":{"rows":3,"cols":3,"spacing":0.1,)"
                        R"("origin":[0,0,1],"axis_u":[1,0,0],"axis_v":[0,1,0],"total_mass":0.09,"stiffness_b":5})";

struct BadScene {
  const char* name;
  std::string text;
  const char* where;    // expected JSON pointer in the message ("" = where the parser stopped)
  const char* problem;  // expected words of the problem
};

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto pos = s.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  if (pos != std::string::npos) s.replace(pos, from.size(), to);
  return s;
}

std::vector<BadScene> bad_scenes() {
  const std::string g = kGood;
  return {
      {"malformed", g.substr(0, g.size() / 2), "", "not valid JSON"},
      {"not_json", "this is not JSON\n", "", "not valid JSON"},
      {"empty", "", "/", "empty file"},
      {"missing_dt", replace(g, "\"dt\":0.01,", ""), "/dt", "missing required key"},
      {"missing_position", replace(g, "{\"position\":[1,0,1],", "{"), "/particles/1/position", "missing required key"},
      {"wrong_type_dt", replace(g, "\"dt\":0.01", "\"dt\":\"0.01\""), "/dt", "expected a number"},
      {"wrong_type_particles", replace(g, "\"particles\":[", "\"particles\":{\"a\":[") + "", "", "not valid JSON"},
      {"negative_mass", replace(g, "\"mass\":2.0", "\"mass\":-2.0"), "/particles/1/mass", "mass must be > 0"},
      {"zero_mass", replace(g, "\"mass\":2.0", "\"mass\":0"), "/particles/1/mass", "mass must be > 0"},
      // 1 / 1e-310 overflows to inf (fuzz_scene: regress_subnormal_mass); 1e-300 is the smallest mass.
      {"subnormal_mass", replace(g, "\"mass\":2.0", "\"mass\":1e-310"), "/particles/1/mass", "mass must be at least 1e-300 kg"},
      {"nan_literal", replace(g, "\"dt\":0.01", "\"dt\":NaN"), "", "not valid JSON"},
      {"inf_literal", replace(g, "\"dt\":0.01", "\"dt\":Infinity"), "", "not valid JSON"},
      {"huge_number", replace(g, "\"position\":[0,0,1]", "\"position\":[0,0,1e400]"), "/particles/0/position/2", "not finite"},
      {"absurd_position", replace(g, "\"position\":[0,0,1]", "\"position\":[0,0,1e200]"), "/particles/0/position/2", "out of range"},
      {"zero_normal", replace(g, "\"normal\":[0,0,1]", "\"normal\":[0,0,0]"), "/planes/0/normal", "must not be zero"},
      {"forward_parallel", replace(g, "\"forward\":[1,0,0]", "\"forward\":[0,0,3]"), "/planes/0/forward", "parallel"},
      {"negative_half_extent", replace(g, "\"half_extents\":[2,2]", "\"half_extents\":[2,-1]"), "/planes/0/half_extents/1", ">= 0"},
      {"dt_zero", replace(g, "\"dt\":0.01", "\"dt\":0"), "/dt", "dt must be > 0"},
      {"dt_negative", replace(g, "\"dt\":0.01", "\"dt\":-0.01"), "/dt", "dt must be > 0"},
      {"spring_out_of_range", replace(g, "\"j\":1", "\"j\":7"), "/springs/0/j", "out of range"},
      {"spring_same_particle", replace(g, "\"j\":1", "\"j\":0"), "/springs/0/j", "two different particles"},
      {"unknown_integrator", replace(g, "\"symplectic\"", "\"verlet\""), "/integrator", "unknown integrator"},
      {"unknown_key", replace(g, "\"gravity\"", "\"gravty\""), "/gravty", "unknown key"},
      {"duplicate_key", replace(g, "\"dt\":0.01,", "\"dt\":0.01,\"dt\":0.02,"), "/", "duplicate key \"dt\""},
      {"elasticity_out_of_range", replace(g, "\"elasticity\":0.5}]", "\"elasticity\":1.5}]"), "/particles/1/elasticity", "outside"},
      {"missing_elasticity_with_planes", replace(g, ",\"elasticity\":0.5}]", "}]"), "/particles/1/elasticity", "missing required key"},
      {"friction_out_of_range", replace(g, "\"friction\":0.5", "\"friction\":2"), "/planes/0/friction", "outside"},
      {"steps_fraction", replace(g, "\"steps\":10", "\"steps\":10.5"), "/steps", "expected an integer"},
      {"steps_negative", replace(g, "\"steps\":10", "\"steps\":-1"), "/steps", "out of range"},
      {"position_short", replace(g, "\"position\":[0,0,1]", "\"position\":[0,1]"), "/particles/0/position", "3 numbers"},
      {"no_particles", replace(g, R"("particles":[{"position":[0,0,1],"velocity":[0,0,0],"mass":1.0,"pinned":false,"elasticity":0.5},
              {"position":[1,0,1],"mass":2.0,"elasticity":0.5}],
 "springs":[{"i":0,"j":1,"stiffness":4.0,"rest_length":1.0}],)", "\"particles\":[],"), "/particles", "no particles"},
      {"negative_stiffness", replace(g, "\"stiffness\":4.0", "\"stiffness\":-4.0"), "/springs/0/stiffness", "outside"},
      {"pinned_not_bool", replace(g, "\"pinned\":false", "\"pinned\":\"no\""), "/particles/0/pinned", "expected true or false"},
      // A cloth is held to the particles' rule: no hidden k where a plane or an obstacle can hit it.
      {"cloth_without_elasticity_with_planes", std::string(kClothNoK) + R"(,"planes":[{"position":[0,0,0],"normal":[0,0,1],)"
                                                R"("forward":[1,0,0],"half_extents":[1,1]}]})",
       "/cloth/elasticity", "missing required key (the scene has planes or obstacles)"},
      {"cloth_without_elasticity_with_obstacle", std::string(kClothNoK) + R"(,"obstacles":[{"sphere":{"center":[0,0,-1],)"
                                                   R"("radius":0.5}}]})",
       "/cloth/elasticity", "missing required key (the scene has planes or obstacles)"},
      // 16.7 M nodes would need ~4 GB and fail in the allocator minutes later (found by fuzz_scene).
      {"huge_cloth", R"({"dt":0.01,"steps":0,"cloth":{"rows":4096,"cols":4096,"spacing":0.001,"origin":[0,0,0],)"
                     R"("axis_u":[1,0,0],"axis_v":[0,1,0],"total_mass":1,"stiffness_b":1}})",
       "/cloth/cols", "more than the limit of 1048576"},
  };
}

TEST(SceneReader, GoodSceneLoads) {
  const Scene s = io::scene_from_json(io::parse_json_text(kGood, "good.json"), "good.json");
  ASSERT_EQ(s.particles.size(), 2u);
  EXPECT_EQ(s.particles.inv_mass[1], 0.5);
  EXPECT_EQ(s.forces.springs.size(), 1u);
  EXPECT_EQ(s.planes.size(), 1u);
  EXPECT_EQ(s.planes[0].right(), Vec3(0, 1, 0));
  EXPECT_FALSE(s.forces.air_drag.has_value());
  EXPECT_FALSE(s.forces.wind.has_value());
  EXPECT_EQ(s.integrator, IntegratorKind::Symplectic);
}

// The cloth's typo of the issue: the allowed keys and both near ones, through the CLI.
TEST(SceneReader, UnknownClothKeySuggestsTheNearest) {
  const auto dir = testing::temp_dir("cloth-typo");
  std::string text = std::string(kClothNoK) + "}";
  text.replace(text.find("\"stiffness_b\""), 13, "\"stiffness\"");
  testing::write_text(dir / "c.json", text);
  const auto r = run_cli("run '" + (dir / "c.json").string() + "'");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(r.err, "tecido: " + (dir / "c.json").string() +
                       ": /cloth/stiffness: unknown key \"stiffness\" (allowed: rows, cols, spacing, origin, axis_u, "
                       "axis_v, total_mass, stiffness_b, stiffness_a, damping, elasticity, pins; did you mean \"stiffness_b\" "
                       "or \"stiffness_a\"?); keys starting with '_' are comments\n");
  std::filesystem::remove_all(dir);
}

// Without a plane or obstacle nothing can bounce the cloth: it needs no k. An obstacle with its
// own elasticity decides its contacts alone: the cloth needs none either. Given, k is the cloth's.
TEST(SceneReader, ClothNeedsElasticityOnlyWhereSomethingCanHitIt) {
  const auto load = [](const std::string& text) { return io::scene_from_json(io::parse_json_text(text, "c.json"), "c.json"); };
  EXPECT_EQ(load(std::string(kClothNoK) + "}").particles.size(), 9u);
  EXPECT_EQ(load(std::string(kClothNoK) + R"(,"obstacles":[{"sphere":{"center":[0,0,-1],"radius":0.5},"elasticity":0.2}]})")
                .particles.size(),
            9u);
  std::string with_k = kClothNoK;
  with_k.replace(with_k.find("\"stiffness_b\":5"), 15, "\"stiffness_b\":5,\"elasticity\":0.25");
  const Scene s = load(with_k + R"(,"planes":[{"position":[0,0,0],"normal":[0,0,1],"forward":[1,0,0],"half_extents":[1,1]}]})");
  ASSERT_EQ(s.particles.size(), 9u);
  for (double k : s.particles.elasticity) EXPECT_EQ(k, 0.25);
}

TEST(SceneReader, EveryBadSceneIsRejectedByTheReaderWithItsPath) {
  for (const BadScene& b : bad_scenes()) {
    try {
      io::scene_from_json(io::parse_json_text(b.text, std::string(b.name) + ".json"), std::string(b.name) + ".json");
      ADD_FAILURE() << b.name << ": accepted";
    } catch (const io::InputError& e) {
      EXPECT_EQ(e.file(), std::string(b.name) + ".json");
      const std::string msg = e.what();
      if (*b.where) {
        EXPECT_NE(msg.find(std::string(": ") + b.where + ":"), std::string::npos) << b.name << ": " << msg;
      }
      EXPECT_NE(msg.find(b.problem), std::string::npos) << b.name << ": " << msg;
    }
  }
}

TEST(SceneReader, CliExitsTwoWithOneLineAndWritesNothing) {
  const auto dir = testing::temp_dir("bad-scenes");
  for (const BadScene& b : bad_scenes()) {
    const auto file = dir / (std::string(b.name) + ".json");
    testing::write_text(file, b.text);
    const auto out = dir / (std::string(b.name) + "-out");
    const auto r = run_cli("run '" + file.string() + "' --json --out '" + out.string() + "'");
    EXPECT_EQ(r.code, 2) << b.name << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << b.name;
    ASSERT_FALSE(r.err.empty()) << b.name;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << b.name << ": " << r.err;
    EXPECT_NE(r.err.find(file.string()), std::string::npos) << b.name << ": " << r.err;
    if (*b.where) {
      EXPECT_NE(r.err.find(std::string(": ") + b.where + ":"), std::string::npos) << b.name << ": " << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(out)) << b.name;
  }
  std::filesystem::remove_all(dir);
}

TEST(SceneReader, DirectoryAndMissingFileAreBadInput) {
  const auto dir = testing::temp_dir("dir-scene");
  auto r = run_cli("run '" + dir.string() + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("is a directory"), std::string::npos) << r.err;
  r = run_cli("run '" + (dir / "nope.json").string() + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no such file"), std::string::npos) << r.err;
  std::filesystem::remove_all(dir);
}

TEST(SceneReader, UnknownEngineAndIntegratorAreUsageErrors) {
  const auto dir = testing::temp_dir("usage");
  testing::write_text(dir / "s.json", kGood);
  auto r = run_cli("run '" + (dir / "s.json").string() + "' --integrator verlet");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--integrator: must be one of euler, symplectic, midpoint, rk4 (got \"verlet\")"), std::string::npos)
      << r.err;
  testing::write_text(dir / "cases.json", R"({"cases":[]})");
  r = run_cli("plane --cases '" + (dir / "cases.json").string() + "' --engines core,bogus --json");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("unknown plane engine \"bogus\""), std::string::npos) << r.err;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido
