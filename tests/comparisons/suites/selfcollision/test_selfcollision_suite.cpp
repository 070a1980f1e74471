// The selfcollision suite as a whole (comparisons/suites/selfcollision/selfcollision_suite.*): a
// source whose case throws fails its own checks with the reason; an engine that invents pairs is
// scored by hand-countable numbers; sharded runs merge into the same checks and data; and with
// every number of its tolerance section changed it reports the same checks after the same work,
// exiting 1 when a band excludes the values; its disagreement file names each engine's invented
// and dropped pairs on the frames where it erred, with those frames' positions.
#include "comparisons/io/source_dir.h"
#include "comparisons/suites/selfcollision/selfcollision_suite.h"

#include "tests/support/cli_runner.h"
#include "tests/support/tolerance_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/cloth/self_collision.h"

#include <algorithm>
#include <stdexcept>

namespace tecido::suites {
namespace {

using testing::run_cli;
using selfcollision::FrameSet;
using selfcollision::Settings;

std::string q(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

FrameSet broken_frames(const Settings&, const std::string&) { throw std::runtime_error("no frames today"); }

std::optional<std::vector<TrianglePair>> brute(const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& t) {
  return self_collision_pairs_brute(x, t);
}
/// The truth plus the pair (first triangle, last triangle) when that pair is not already in it.
std::optional<std::vector<TrianglePair>> brute_plus_one(const std::vector<Vec3>& x,
                                                        const std::vector<std::array<int, 3>>& t) {
  auto p = self_collision_pairs_brute(x, t);
  const TrianglePair extra{0, static_cast<int>(t.size()) - 1};
  if (!std::binary_search(p.begin(), p.end(), extra)) p.insert(std::upper_bound(p.begin(), p.end(), extra), extra);
  return p;
}

/// The truth without its first pair.
std::optional<std::vector<TrianglePair>> brute_minus_first(const std::vector<Vec3>& x,
                                                           const std::vector<std::array<int, 3>>& t) {
  auto p = self_collision_pairs_brute(x, t);
  if (!p.empty()) p.erase(p.begin());
  return p;
}

TEST(SelfcollisionSuite, AThrowingSourceFailsItsChecksAndAnInventedPairCosts) {
  const Tolerances tol(io::Json::parse(R"({"selfcollision":{"core_min":1,"plus-one_min":0}})"), "tol.json");
  const auto dir = testing::temp_dir("selfcollision-throwing");
  SuiteContext ctx;
  ctx.out_dir = dir.string();
  ctx.tolerances = &tol;
  ctx.data_dir = std::string(TECIDO_SOURCE_DIR) + "/data";
  const Settings set = selfcollision::settings(true);
  std::vector<selfcollision::FrameSource> sources = {selfcollision::frame_sources().at(1), {"broken", "throws", &broken_frames}};
  const std::vector<SelfCollisionEngine> engines = {
      self_collision_engines().front(), {"plus-one", &brute_plus_one}, {"core-brute", &brute}};
  const Sweep s = selfcollision_sweep_for(ctx, set, sources, engines);
  ASSERT_EQ(s.cases, 2u);
  const SuiteResult r = s.assemble(run_sweep_cases(s, {0, 1}, 2, "t", false));
  ASSERT_EQ(r.checks.size(), 8u);
  for (const Check& c : r.checks) {
    if (c.name.find("/broken/") != std::string::npos) {
      EXPECT_FALSE(c.pass);
      EXPECT_NE(c.reason.find("no frames today"), std::string::npos) << c.name << ": " << c.reason;
    }
  }
  EXPECT_EQ(r.checks[0].name, "selfcollision/core/crumple/precision");
  EXPECT_TRUE(r.checks[0].pass && r.checks[1].pass);
  // plus-one reports every true pair and one more per frame (unless it was true): count by hand.
  const auto crumple = selfcollision::crumple_frames(set, ctx.data_dir);
  long truth = 0, extra = 0;
  for (const auto& f : crumple.frames) {
    const auto p = self_collision_pairs_brute(f.x, crumple.triangles);
    truth += static_cast<long>(p.size());
    extra += std::binary_search(p.begin(), p.end(), TrianglePair{0, static_cast<int>(crumple.triangles.size()) - 1}) ? 0 : 1;
  }
  ASSERT_GT(truth, 0);
  EXPECT_EQ(r.checks[4].name, "selfcollision/plus-one/crumple/precision");
  EXPECT_DOUBLE_EQ(r.checks[4].value, static_cast<double>(truth) / static_cast<double>(truth + extra));
  EXPECT_DOUBLE_EQ(r.checks[5].value, 1.0);
  EXPECT_NE(r.markdown.find(std::to_string(extra) + " pairs that do not intersect"), std::string::npos) << r.markdown;
  std::filesystem::remove_all(dir);
}

TEST(SelfcollisionSuite, DisagreementFileNamesTheInventedAndTheDroppedPairs) {
  const Tolerances tol(io::Json::parse(R"({"selfcollision":{"plus-one_min":0,"minus-first_min":0}})"), "tol.json");
  const auto dir = testing::temp_dir("selfcollision-disagreements");
  SuiteContext ctx;
  ctx.out_dir = dir.string();
  ctx.tolerances = &tol;
  ctx.data_dir = std::string(TECIDO_SOURCE_DIR) + "/data";
  const Settings set = selfcollision::settings(true);
  const std::vector<SelfCollisionEngine> engines = {
      {"plus-one", &brute_plus_one}, {"minus-first", &brute_minus_first}, {"core-brute", &brute}};
  const Sweep s = selfcollision_sweep_for(ctx, set, {selfcollision::frame_sources().at(1)}, engines);
  const SuiteResult r = s.assemble(run_sweep_cases(s, {0}, 1, "t", false));
  // By hand: plus-one errs on the frames without the pair (0, last), minus-first on those with a true pair.
  const auto crumple = selfcollision::crumple_frames(set, ctx.data_dir);
  const TrianglePair last{0, static_cast<int>(crumple.triangles.size()) - 1};
  nlohmann::json want = nlohmann::json::array();
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t f = 0; f < crumple.frames.size(); ++f) {
      const auto p = self_collision_pairs_brute(crumple.frames[f].x, crumple.triangles);
      if (pass == 0 && !std::binary_search(p.begin(), p.end(), last))
        want.push_back({{"engine", "plus-one"}, {"frame", f}, {"missed", nlohmann::json::array()}, {"extra", {last}}});
      if (pass == 1 && !p.empty())
        want.push_back({{"engine", "minus-first"}, {"frame", f}, {"missed", {p.front()}}, {"extra", nlohmann::json::array()}});
    }
  ASSERT_GE(want.size(), 2u);
  const auto doc = nlohmann::json::parse(testing::slurp(dir / "selfcollision" / "disagreements.json"));
  EXPECT_EQ(doc["truth"], "core-brute");
  nlohmann::json got = nlohmann::json::array();
  for (const auto& e : doc["entries"])
    got.push_back({{"engine", e["engine"]}, {"frame", e["frame"]}, {"missed", e["missed"]}, {"extra", e["extra"]}});
  if (want.size() > set.max_entries_per_source) want.erase(want.begin() + static_cast<long>(set.max_entries_per_source), want.end());
  EXPECT_EQ(got, want);
  // Each kept frame's positions are the recorded ones, exactly.
  ASSERT_EQ(doc["sources"].size(), 1u);
  EXPECT_EQ(doc["sources"][0]["triangles"], nlohmann::json(crumple.triangles));
  for (const auto& f : doc["sources"][0]["frames"]) {
    const auto& x = crumple.frames.at(f["frame"].get<std::size_t>()).x;
    ASSERT_EQ(f["x"].size(), 3 * x.size());
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_EQ(f["x"][3 * i + 1].get<double>(), x[i][1]);
  }
  ASSERT_FALSE(r.views.empty());
  EXPECT_EQ(r.views[0].href, "selfcollision/disagreements.html");
  EXPECT_EQ(r.views.size(), 1 + got.size());
  EXPECT_TRUE(std::filesystem::exists(dir / "selfcollision" / "disagreements.data.js"));
  EXPECT_NE(r.markdown.find("selfcollision/disagreements.json"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(SelfcollisionSuite, ShardsMergeIntoTheSameChecksAndData) {
  const auto dir = testing::temp_dir("selfcollision-shards");
  ASSERT_EQ(run_cli("suite selfcollision --quick --out " + q(dir / "full")).code, 0);
  ASSERT_EQ(run_cli("suite selfcollision --quick --shard 1/2 --out " + q(dir / "s1")).code, 0);
  ASSERT_EQ(run_cli("suite selfcollision --quick --shard 0/2 --out " + q(dir / "s0")).code, 0);
  const auto m = run_cli("merge " + q(dir / "s0") + " " + q(dir / "s1") + " --out " + q(dir / "merged"));
  ASSERT_EQ(m.code, 0) << m.err;
  const auto full = nlohmann::json::parse(testing::slurp(dir / "full" / "report.json"));
  const auto merged = nlohmann::json::parse(testing::slurp(dir / "merged" / "report.json"));
  EXPECT_EQ(full["suites"][0]["checks"], merged["suites"][0]["checks"]);
  EXPECT_EQ(testing::data_without_timings(full), testing::data_without_timings(merged));
  // No built-in engine disagrees here: the file is written all the same, with no entry.
  EXPECT_EQ(testing::slurp(dir / "full" / "selfcollision" / "disagreements.json"),
            testing::slurp(dir / "merged" / "selfcollision" / "disagreements.json"));
  const auto doc = nlohmann::json::parse(testing::slurp(dir / "full" / "selfcollision" / "disagreements.json"));
  EXPECT_EQ(doc["entries"], nlohmann::json::array());
  std::filesystem::remove_all(dir);
}

TEST(SelfcollisionSuite, EveryToleranceChangedSameChecksSameWork) {
  const auto dir = testing::temp_dir("selfcollision-tolerances");
  const auto base = run_cli("suite selfcollision --quick --out " + q(dir / "base"));
  ASSERT_EQ(base.code, 0) << base.err;
  const auto want = nlohmann::json::parse(testing::slurp(dir / "base" / "report.json"));
  ASSERT_FALSE(testing::check_names(want).empty());
  // Lowered: every band still holds the values. Raised: every lower bound above 1, so every check fails.
  ASSERT_GT(testing::write_changed_tolerances(dir / "low.json", {"selfcollision"}, [](double x) { return 0.5 * x - 0.25; }), 0);
  testing::write_changed_tolerances(dir / "high.json", {"selfcollision"}, [](double x) { return x + 0.5; });
  for (const std::string name : {"low", "high"}) {
    const auto r = run_cli("suite selfcollision --quick --tolerances " + q(dir / (name + ".json")) + " --out " + q(dir / name));
    const auto got = nlohmann::json::parse(testing::slurp(dir / name / "report.json"));
    EXPECT_EQ(testing::check_names(got), testing::check_names(want)) << name;
    EXPECT_EQ(testing::data_without_timings(got), testing::data_without_timings(want)) << name << ": other work";
    EXPECT_EQ(r.code, name == "high" ? 1 : 0) << name << ": " << r.err;
    for (const auto& c : got["suites"][0]["checks"]) EXPECT_EQ(c["pass"].get<bool>(), name == "low") << c.dump();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido::suites
