// The public engine (include/tecido/simulation.h, harness::load_scene) and the public self-collision
// functions (tecido/core.h, tecido/referee.h) against the command line and the exact referee:
// a scene file loaded and run in code gives the bits `tecido run --json` prints; a scene built in
// code gives the bits of the file that describes it; a bad file gives the command line's line;
// self_collisions and continuous_self_collisions give `tecido selfcollide`'s pairs, which equal
// the exact referee's on every pair (the brute force written here).
#include "comparisons/io/source_dir.h"
#include "tests/support/cli_runner.h"

#include <tecido/core.h>
#include <tecido/harness.h>
#include <tecido/referee.h>
#include <tecido/simulation.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

namespace {

using nlohmann::json;
using tecido::Vec3;
using tecido::testing::quoted;
using tecido::testing::run_cli;
namespace tc = tecido::core;

std::string scene_path(const std::string& name) { return std::string(TECIDO_SOURCE_DIR) + "/data/scenes/" + name; }

/// `tecido run FILE --json --steps N`'s particles equal the simulation's, bit for bit (17
/// significant digits round-trip), and the status agrees.
void expect_same_as_tecido_run(const std::string& file, long long steps, const tc::Simulation& sim) {
  const auto r = run_cli("run " + quoted(file) + " --json --steps " + std::to_string(steps));
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["status"].get<std::string>(), sim.diverged() ? "unstable" : "ok");
  EXPECT_EQ(j["steps"].get<long long>(), sim.steps_done());
  EXPECT_EQ(j["contacts"]["events"].get<long long>(), sim.contacts().events);
  const json& ps = j["particles"];
  ASSERT_EQ(ps.size(), sim.positions().size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < ps.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      differ += ps[i]["x"][k].get<double>() != sim.positions()[i][k];
      differ += ps[i]["v"][k].get<double>() != sim.velocities()[i][k];
    }
  EXPECT_EQ(differ, 0u) << file;
}

TEST(EngineFacade, ALoadedSceneRunsBitForBitAsTecidoRun) {
  // Planes (fig. 9), a cloth on a sphere, a cloth with self-collision (fig. 21), restitution.
  for (const char* name : {"seed_fig9_four_particles.json", "cloth_on_sphere.json", "seed_fig21_self_contact.json",
                           "bounce_restitution.json"}) {
    const tc::Scene scene = tecido::harness::load_scene(scene_path(name));
    const long long steps = std::min(scene.steps(), 300LL);
    tc::Simulation sim(scene);
    sim.run(steps);
    expect_same_as_tecido_run(scene_path(name), steps, sim);
  }
}

// A cloth pinned at two corners falling past a sphere onto a tilted plane, with a free particle
// tied to a corner, in the order the file lists them (planes, particles, cloth, springs).
const char* kSceneFile = R"({"integrator":"midpoint","dt":0.002,"steps":400,"gravity":[0,0,-9.81],"air_drag":0.01,
 "planes":[{"position":[0.3,0.3,-0.6],"normal":[0.1,0,1],"forward":[1,0,0],"half_extents":[2,2],"friction":0.3}],
 "obstacles":[{"sphere":{"center":[0.35,0.35,-0.25],"radius":0.15},"friction":0.2},
              {"box":{"center":[-0.5,0,-0.3],"half_extents":[0.1,0.2,0.3]},"elasticity":0.1,"velocity":[0.5,0,0]}],
 "particles":[{"position":[0.9,0.9,0.3],"velocity":[0,0,1],"mass":0.05,"elasticity":0.4}],
 "cloth":{"rows":8,"cols":8,"spacing":0.1,"origin":[0,0,0],"axis_u":[1,0,0],"axis_v":[0,1,0],"total_mass":0.3,
          "stiffness_b":80,"stiffness_a":20,"damping":0.01,"elasticity":0.3,"pins":[[0,0],[7,0]]},
 "springs":[{"i":0,"j":64,"stiffness":5}]})";

tc::Scene scene_in_code() {
  tc::Scene s;
  s.set_integrator(tc::Integrator::Midpoint).set_dt(0.002).set_steps(400).set_gravity(Vec3(0, 0, -9.81)).set_air_drag(0.01);
  tecido::Rectangle floor;
  floor.position = Vec3(0.3, 0.3, -0.6);
  floor.normal = Vec3(0.1, 0, 1);
  floor.forward = Vec3(1, 0, 0);
  floor.half_forward = floor.half_right = 2;
  s.add_plane(floor, 0.3);
  tc::Sphere ball;
  ball.center = Vec3(0.35, 0.35, -0.25);
  ball.radius = 0.15;
  ball.friction = 0.2;
  s.add_sphere(ball);
  tc::Box box;
  box.center = Vec3(-0.5, 0, -0.3);
  box.half_extents = Vec3(0.1, 0.2, 0.3);
  box.elasticity = 0.1;
  box.velocity = Vec3(0.5, 0, 0);
  s.add_box(box);
  const int loose = s.add_particle(Vec3(0.9, 0.9, 0.3), Vec3(0, 0, 1), 0.05, 0.4);
  tc::ClothGrid g;
  g.rows = g.cols = 8;
  g.spacing = 0.1;
  g.total_mass = 0.3;
  g.stiffness = 80;
  g.bend_stiffness = 20;
  g.damping = 0.01;
  g.elasticity = 0.3;
  g.pins = {{0, 0}, {7, 0}};
  const int first = s.add_cloth(g);
  s.add_spring(loose, first + 63, 5);
  return s;
}

TEST(EngineFacade, ASceneBuiltInCodeRunsBitForBitAsItsFile) {
  const auto dir = tecido::testing::temp_dir("facade");
  const std::string file = (dir / "scene.json").string();
  tecido::testing::write_text(file, kSceneFile);
  const tc::Scene scene = scene_in_code();
  tc::Simulation sim(scene);
  sim.run(scene.steps());
  EXPECT_GT(sim.contacts().events, 0);  // the cloth reached the plane or the sphere
  EXPECT_GT(sim.contacts().obstacle_contacts, 0);
  expect_same_as_tecido_run(file, scene.steps(), sim);
  std::filesystem::remove_all(dir);
}

TEST(EngineFacade, ABadSceneFileGivesTheCommandLinesMessage) {
  const auto dir = tecido::testing::temp_dir("facade-bad");
  const std::string file = (dir / "bad.json").string();
  tecido::testing::write_text(file, R"({"dt":-1,"steps":3,"particles":[{"position":[0,0,0],"mass":1}]})");
  const auto r = run_cli("run " + quoted(file));
  EXPECT_EQ(r.code, 2);
  try {
    tecido::harness::load_scene(file);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ("tecido: " + std::string(e.what()) + "\n", r.err);
    EXPECT_NE(std::string(e.what()).find("/dt"), std::string::npos);
  }
  EXPECT_THROW(tecido::harness::load_scene((dir / "missing.json").string()), std::runtime_error);
  std::filesystem::remove_all(dir);
}

/// Two 6 x 6 sheets, 0.1 m spacing: A in the plane z = 0, B in the plane y = 0.25 crossing it
/// (x, z from -0.25), both jittered by fixed offsets so no test sits on a tie. B moves down by
/// 0.3 m over the step (`drop`).
struct TwoSheets {
  std::vector<Vec3> V;
  tecido::Faces F;
};

TwoSheets two_sheets(double drop) {
  TwoSheets m;
  const int n = 6;
  for (int sheet = 0; sheet < 2; ++sheet) {
    const int base = static_cast<int>(m.V.size());
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        const double jitter = 0.013 * std::sin(7.0 * r + 3.0 * c + sheet);
        m.V.push_back(sheet == 0 ? Vec3(0.1 * c, 0.1 * r, jitter)
                                 : Vec3(0.1 * c + 0.05, 0.25 + jitter, 0.1 * r - 0.25 - drop));
      }
    for (int r = 0; r + 1 < n; ++r)
      for (int c = 0; c + 1 < n; ++c) {
        const int a = base + r * n + c, b = a + 1, d = a + n + 1, e = a + n;
        m.F.push_back({a, b, d});
        m.F.push_back({a, d, e});
      }
  }
  return m;
}

bool share_vertex(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  for (int x : a)
    for (int y : b)
      if (x == y) return true;
  return false;
}

tecido::Triangle corners(const TwoSheets& m, int f) { return {m.V[m.F[f][0]], m.V[m.F[f][1]], m.V[m.F[f][2]]}; }

void write_obj(const std::string& path, const TwoSheets& m) {
  std::string text;
  char line[128];
  for (const Vec3& v : m.V) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", v.x(), v.y(), v.z());
    text += line;
  }
  for (const auto& f : m.F) text += "f " + std::to_string(f[0] + 1) + " " + std::to_string(f[1] + 1) + " " + std::to_string(f[2] + 1) + "\n";
  tecido::testing::write_text(path, text);
}

TEST(EngineFacade, SelfCollisionsAreTheExactPairsAndSelfcollidesAnswer) {
  const TwoSheets m = two_sheets(0.0);
  std::vector<tecido::FacePair> truth;  // the exact referee on every pair without a shared vertex
  for (int i = 0; i < static_cast<int>(m.F.size()); ++i)
    for (int j = i + 1; j < static_cast<int>(m.F.size()); ++j)
      if (!share_vertex(m.F[i], m.F[j]) && tecido::referee::tri_tri(corners(m, i), corners(m, j))) truth.push_back({i, j});
  ASSERT_GT(truth.size(), 4u);  // the sheets cross
  EXPECT_EQ(tc::self_collisions(m.V, m.F), truth);

  const auto dir = tecido::testing::temp_dir("facade-selfcollide");
  write_obj((dir / "m.obj").string(), m);
  const auto r = run_cli("selfcollide --mesh " + quoted((dir / "m.obj").string()) + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(json::parse(r.out)["core"].get<std::vector<tecido::FacePair>>(), truth);
  std::filesystem::remove_all(dir);
}

TEST(EngineFacade, ContinuousSelfCollisionsAreTheExactContactsAndSelfcollidesAnswer) {
  const TwoSheets a = two_sheets(-0.15), b = two_sheets(0.15);  // sheet B moves down 0.3 m through A
  // The exact referee on every vertex-face pair and every edge-edge pair sharing no vertex.
  tecido::SelfContacts truth;
  std::set<tecido::Edge> edge_set;
  for (const auto& f : a.F)
    for (int k = 0; k < 3; ++k) edge_set.insert({std::min(f[k], f[(k + 1) % 3]), std::max(f[k], f[(k + 1) % 3])});
  const std::vector<tecido::Edge> edges(edge_set.begin(), edge_set.end());
  tecido::Motion q;
  for (int v = 0; v < static_cast<int>(a.V.size()); ++v)
    for (int f = 0; f < static_cast<int>(a.F.size()); ++f) {
      const auto& t = a.F[f];
      if (t[0] == v || t[1] == v || t[2] == v) continue;
      q.kind = tecido::MotionKind::VertexFace;
      q.x0 = {a.V[v], a.V[t[0]], a.V[t[1]], a.V[t[2]]};
      q.x1 = {b.V[v], b.V[t[0]], b.V[t[1]], b.V[t[2]]};
      if (tecido::referee::ccd(q).hit) truth.vertex_face.push_back({v, f});
    }
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const tecido::Edge e = edges[i], g = edges[j];
      if (e[0] == g[0] || e[0] == g[1] || e[1] == g[0] || e[1] == g[1]) continue;
      q.kind = tecido::MotionKind::EdgeEdge;
      q.x0 = {a.V[e[0]], a.V[e[1]], a.V[g[0]], a.V[g[1]]};
      q.x1 = {b.V[e[0]], b.V[e[1]], b.V[g[0]], b.V[g[1]]};
      if (tecido::referee::ccd(q).hit) truth.edge_edge.push_back({e, g});
    }
  ASSERT_GT(truth.vertex_face.size(), 4u);
  ASSERT_GT(truth.edge_edge.size(), 4u);

  const tecido::SelfContacts exact = tecido::referee::continuous_self_collisions(a.V, b.V, a.F, 2);
  EXPECT_EQ(exact.vertex_face, truth.vertex_face);
  EXPECT_EQ(exact.edge_edge, truth.edge_edge);
  // Core's answer is conservative: every exact contact, and only near misses besides.
  const tecido::SelfContacts core = tc::continuous_self_collisions(a.V, b.V, a.F);
  for (const auto& p : truth.vertex_face)
    EXPECT_TRUE(std::binary_search(core.vertex_face.begin(), core.vertex_face.end(), p));
  for (const auto& p : truth.edge_edge) EXPECT_TRUE(std::binary_search(core.edge_edge.begin(), core.edge_edge.end(), p));

  const auto dir = tecido::testing::temp_dir("facade-selfcollide-to");
  write_obj((dir / "a.obj").string(), a);
  write_obj((dir / "b.obj").string(), b);
  const auto r = run_cli("selfcollide --mesh " + quoted((dir / "a.obj").string()) + " --to " +
                         quoted((dir / "b.obj").string()) + " --engines core,core-brute --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  using VertexFaces = std::vector<std::array<int, 2>>;
  using EdgeEdges = std::vector<std::array<tecido::Edge, 2>>;
  EXPECT_EQ(j["core"]["vertex_face"].get<VertexFaces>(), exact.vertex_face);
  EXPECT_EQ(j["core"]["edge_edge"].get<EdgeEdges>(), exact.edge_edge);
  EXPECT_EQ(j["core-brute"]["vertex_face"].get<VertexFaces>(), core.vertex_face);
  EXPECT_EQ(j["core-brute"]["edge_edge"].get<EdgeEdges>(), core.edge_edge);
  std::filesystem::remove_all(dir);
}

TEST(EngineFacade, SelfCollisionArgumentsAreChecked) {
  const TwoSheets m = two_sheets(0.0);
  tecido::Faces bad = m.F;
  bad[3][1] = static_cast<int>(m.V.size());
  EXPECT_THROW(tc::self_collisions(m.V, bad), std::invalid_argument);
  std::vector<Vec3> nan = m.V;
  nan[5].y() = NAN;
  EXPECT_THROW(tc::self_collisions(nan, m.F), std::domain_error);
  std::vector<Vec3> shorter(m.V.begin(), m.V.end() - 1);
  EXPECT_THROW(tecido::referee::continuous_self_collisions(m.V, shorter, m.F), std::invalid_argument);
}

/// The ```cpp blocks of docs/package.md after the heading `heading`, before the next heading.
std::vector<std::string> cpp_blocks_under(const std::string& markdown, const std::string& heading) {
  std::vector<std::string> blocks;
  std::size_t at = markdown.find("\n" + heading + "\n");
  if (at == std::string::npos) return blocks;
  const std::size_t end = std::min(markdown.find("\n#", at + heading.size() + 2), markdown.size());
  while ((at = markdown.find("```cpp\n", at)) < end) {
    const std::size_t body = at + 7, close = markdown.find("```", body);
    blocks.push_back(markdown.substr(body, close - body));
    at = close + 3;
  }
  return blocks;
}

TEST(EngineFacade, ThePackagePagesExampleIsTheConsumersCode) {
  const std::string doc = tecido::testing::slurp(std::string(TECIDO_SOURCE_DIR) + "/docs/package.md");
  const std::string code =
      tecido::testing::slurp(std::string(TECIDO_SOURCE_DIR) + "/examples/consumer/tests/test_my_cloth_vs_tecido.cpp");
  const std::vector<std::string> blocks = cpp_blocks_under(doc, "### A scene in code");
  ASSERT_EQ(blocks.size(), 2u);
  for (const std::string& b : blocks) EXPECT_NE(code.find(b), std::string::npos) << b;
}

}  // namespace
