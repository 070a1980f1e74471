// Outside engines answering continuous collision, as a user runs them: the example plug-in's
// sampled test (known to miss a tangent touch between its instants) and the Python example's
// cubic-root test through `tecido ccd` and `tecido suite ccd`; their misses counted against the
// exact referee, and a failing check for the engine that misses contacts.
#include "comparisons/io/ccd_queries.h"
#include "tests/support/cli_runner.h"
#include "tests/support/outside_fixtures.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <filesystem>

namespace tecido {
namespace {

using nlohmann::json;
using testing::quoted;
using testing::run_cli;

CcdQuery query(CcdKind kind, std::array<Vec3, 4> x0, std::array<Vec3, 4> x1) {
  CcdQuery q;
  q.kind = kind;
  q.x0 = x0;
  q.x1 = x1;
  return q;
}

/// Hand-worked queries (dyadic, so exact's answers are the ones worked here), with their truth.
/// "tangent": triangle a = 0, b = (1,0,0), c = (0, 1, 1 - 2t) (normal (0, -(1 - 2t), 1)); the vertex
/// p = (1/4, 1/4 + t/2, 17/64 - t/4). Their coplanarity is -(t - 1/8)^2: the vertex touches the
/// plane at t = 1/8 only, where p = b/4 + 5c/16 lies inside the triangle (1/4 + 5/16 <= 1). A test
/// that samples its sign at t = 0, 1/4, ..., 1 sees it negative at every instant and misses it.
std::vector<io::CcdQueryEntry> hand_queries() {
  const auto vf = CcdKind::VertexFace, ee = CcdKind::EdgeEdge;
  std::vector<io::CcdQueryEntry> out(4);
  out[0].id = "tangent";
  out[0].query = query(vf, {Vec3(0.25, 0.25, 0.265625), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 1)},
                       {Vec3(0.25, 0.75, 0.015625), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, -1)});
  out[0].truth = true;
  // The vertex falls straight through a still triangle's interior at t = 1/2.
  out[1].id = "through";
  out[1].query = query(vf, {Vec3(0.25, 0.25, 1), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)},
                       {Vec3(0.25, 0.25, -1), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)});
  out[1].truth = true;
  // Edge (0..1, 0, z) falls through the still edge x = 1/2 in z = 0 at t = 1/2, at (1/2, 0, 0).
  out[2].id = "cross";
  out[2].query = query(ee, {Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0.5, -1, 0), Vec3(0.5, 1, 0)},
                       {Vec3(0, 0, -1), Vec3(1, 0, -1), Vec3(0.5, -1, 0), Vec3(0.5, 1, 0)});
  out[2].truth = true;
  // The same fall beside the still edge, moved to x = 5/2: the segments never meet.
  out[3].id = "beside";
  out[3].query = query(ee, {Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(2.5, -1, 0), Vec3(2.5, 1, 0)},
                       {Vec3(0, 0, -1), Vec3(1, 0, -1), Vec3(2.5, -1, 0), Vec3(2.5, 1, 0)});
  out[3].truth = false;
  return out;
}

std::string hand_file(const std::filesystem::path& dir) {
  const std::string path = (dir / "queries.json").string();
  testing::write_text(path, io::ccd_queries_to_json(hand_queries()).dump());
  return path;
}

TEST(CliOutsideCcd, ThePluginsSampledTestMissesTheTangentTouch) {
  const auto dir = testing::temp_dir("outside-ccd-plugin");
  const auto r = run_cli("ccd --queries " + quoted(hand_file(dir)) + " --plugin " + quoted(testing::kExamplePlugin) +
                         " --engines exact,sampled-ccd --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json out = json::parse(r.out);
  const auto hand = hand_queries();
  ASSERT_EQ(out["results"].size(), hand.size());
  for (std::size_t k = 0; k < hand.size(); ++k) {
    EXPECT_EQ(out["results"][k]["exact"]["hit"], *hand[k].truth) << hand[k].id;
    EXPECT_EQ(out["results"][k]["sampled-ccd"]["hit"], k != 0 && *hand[k].truth) << hand[k].id;
  }
  EXPECT_EQ(out["results"][0]["exact"]["toi"], 0.125);
  EXPECT_EQ(out["results"][1]["sampled-ccd"]["toi"], 0.5);  // a sign change at the sample t = 1/2 itself
  EXPECT_NE(r.err.find("tecido ccd: exact: 0 false positives, 0 false negatives of 4 queries"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("tecido ccd: sampled-ccd: 0 false positives, 1 false negatives of 4 queries"), std::string::npos)
      << r.err;
  std::filesystem::remove_all(dir);
}

TEST(CliOutsideCcd, ThePythonCubicFindsEveryContact) {
  const auto dir = testing::temp_dir("outside-ccd-python");
  const auto r = run_cli("ccd --queries " + quoted(hand_file(dir)) + " --engine-cmd " +
                         quoted("py=" + testing::kPythonEngine) + " --engines py,exact --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json out = json::parse(r.out);
  const auto hand = hand_queries();
  for (std::size_t k = 0; k < hand.size(); ++k) EXPECT_EQ(out["results"][k]["py"]["hit"], *hand[k].truth) << hand[k].id;
  EXPECT_NEAR(out["results"][0]["py"]["toi"].get<double>(), 0.125, 1e-6);  // a double root, found to about its sqrt
  EXPECT_NEAR(out["results"][2]["py"]["toi"].get<double>(), 0.5, 1e-12);
  EXPECT_NE(r.err.find("tecido ccd: py: 0 false positives, 0 false negatives of 4 queries"), std::string::npos) << r.err;
  std::filesystem::remove_all(dir);
}

const json* find_check(const json& report, const std::string& name) {
  for (const auto& s : report["suites"])
    for (const auto& c : s["checks"])
      if (c["name"] == name) return &c;
  return nullptr;
}

TEST(CliOutsideCcd, SuiteCatchesThePluginsMissesAndItsDisagreementsReplay) {
  const auto dir = testing::temp_dir("outside-ccd-suite");
  const std::string plugin = " --plugin " + quoted(testing::kExamplePlugin);
  const auto r = run_cli("suite ccd --quick --threads 2" + plugin + " --engines sampled-ccd --out " + quoted(dir.string()));
  EXPECT_EQ(r.code, 1) << r.err;  // the sampled test misses contacts on random motion: its checks fail
  const json report = json::parse(testing::slurp(dir / "report.json"));
  const json& data = report["suites"][0]["data"];
  long random_misses = 0;
  for (const char* family : {"vertex-face/random", "edge-edge/random"}) {
    ASSERT_TRUE(data[family]["engines"].contains("sampled-ccd")) << family;
    EXPECT_FALSE(data[family]["engines"].contains("core")) << family;  // --engines ran the referee and the plug-in only
    random_misses += data[family]["engines"]["sampled-ccd"]["fn"].get<long>();
    EXPECT_EQ(data[family]["engines"]["exact"]["fn"], 0) << family;
  }
  EXPECT_GT(random_misses, 0);
  const json* vf = find_check(report, "ccd/vertex-face/random/sampled-ccd/false_negative_rate");
  const json* ee = find_check(report, "ccd/edge-edge/random/sampled-ccd/false_negative_rate");
  ASSERT_TRUE(vf && ee);
  EXPECT_EQ((*vf)["tolerance"], "/ccd/outside_random_max_fn_rate");
  EXPECT_FALSE((*vf)["pass"].get<bool>() && (*ee)["pass"].get<bool>());
  EXPECT_EQ(find_check(report, "ccd/vertex-face/crossing/sampled-ccd/false_negative_rate"), nullptr);  // random only
  EXPECT_EQ(find_check(report, "ccd/vertex-face/random/core/false_negatives"), nullptr);  // core did not run
  // The disagreements replay through `tecido ccd` with the referee's answers as the truth.
  const auto replay = run_cli("ccd --queries " + quoted((dir / "ccd" / "disagreements.json").string()) + plugin +
                              " --engines exact,sampled-ccd --json");
  ASSERT_EQ(replay.code, 0) << replay.err;
  EXPECT_NE(replay.err.find("tecido ccd: exact: 0 false positives, 0 false negatives"), std::string::npos) << replay.err;
  EXPECT_EQ(replay.err.find("sampled-ccd: 0 false positives, 0 false negatives"), std::string::npos) << replay.err;
  EXPECT_NE(testing::slurp(dir / "report.md").find("plug-in " + testing::kExamplePlugin), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(CliOutsideCcd, SuiteChecksThePythonEngineOnRandomMotion) {
  const auto dir = testing::temp_dir("outside-ccd-suite-py");
  const auto r = run_cli("suite ccd --quick --threads 2 --engine-cmd " + quoted("py=" + testing::kPythonEngine) +
                         " --engines py --out " + quoted(dir.string()));
  const json report = json::parse(testing::slurp(dir / "report.json"));
  for (const char* kind : {"vertex-face", "edge-edge"})
    for (const char* what : {"false_negative_rate", "false_positive_rate", "unanswered_rate"}) {
      const json* c = find_check(report, std::string("ccd/") + kind + "/random/py/" + what);
      ASSERT_NE(c, nullptr) << kind << " " << what;
      EXPECT_TRUE((*c)["pass"].get<bool>()) << c->dump();
    }
  EXPECT_EQ(r.code, 0) << r.err;
  const std::string md = testing::slurp(dir / "report.md");
  EXPECT_NE(md.find("its ns/query includes the round trips of its door"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(CliOutsideCcd, AKindTheEngineDoesNotModelIsNullAndReported) {
  const auto dir = testing::temp_dir("outside-ccd-kind");
  const std::string plugin = " --plugin " + quoted(testing::kLiarPlugin);  // its sampled-ccd: vertex-face only
  const auto r = run_cli("ccd --queries " + quoted(hand_file(dir)) + plugin + " --engines exact,sampled-ccd --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json out = json::parse(r.out);
  EXPECT_TRUE(out["results"][1]["sampled-ccd"].is_object());  // vertex-face
  EXPECT_TRUE(out["results"][2]["sampled-ccd"].is_null());    // edge-edge
  EXPECT_NE(r.err.find("sampled-ccd: 0 false positives, 1 false negatives of 2 queries; no answer on 2"),
            std::string::npos) << r.err;
  const auto s = run_cli("suite ccd --quick --threads 2" + plugin + " --engines sampled-ccd --out " + quoted(dir.string()));
  EXPECT_EQ(s.code, 1) << s.err;  // its vertex-face misses still fail
  const json report = json::parse(testing::slurp(dir / "report.json"));
  EXPECT_NE(find_check(report, "ccd/vertex-face/random/sampled-ccd/false_negative_rate"), nullptr);
  EXPECT_EQ(find_check(report, "ccd/edge-edge/random/sampled-ccd/false_negative_rate"), nullptr);
  EXPECT_EQ(find_check(report, "ccd/edge-edge/random/sampled-ccd/unanswered_rate"), nullptr);
  EXPECT_NE(testing::slurp(dir / "report.md").find("edge-edge: not modelled by sampled-ccd."), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido
