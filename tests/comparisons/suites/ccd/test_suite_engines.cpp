// Which engines the ccd suite runs (--engines, outside engines answering ccd) and how a block of
// queries reaches an outside engine: the example plug-in's sampled test, whose answers on a
// still triangle crossed at a sample instant are worked by hand, and its liar copy without an
// edge-edge test, whose edge-edge queries stay unanswered.
#include "comparisons/suites/ccd/suite_engines.h"

#include "comparisons/engines/outside/outside_engines.h"
#include "comparisons/engines/outside/plugin_engine.h"
#include "comparisons/engines/outside/plugin_library.h"
#include "tests/support/outside_fixtures.h"

#include <gtest/gtest.h>

namespace tecido::suites::ccd {
namespace {

std::shared_ptr<outside::OutsideEngines> loaded(const std::string& path) {
  auto all = std::make_shared<outside::OutsideEngines>();
  for (auto& e : outside::plugin_engines(outside::PluginLibrary::load(path))) all->add(e);
  return all;
}

std::vector<std::string> names(const std::vector<SuiteEngine>& engines) {
  std::vector<std::string> out;
  for (const auto& e : engines) out.push_back(e.name);
  return out;
}

const SuiteEngine& named(const std::vector<SuiteEngine>& engines, const std::string& name) {
  for (const auto& e : engines)
    if (e.name == name) return e;
  throw std::logic_error("no engine " + name);
}

TEST(CcdSuiteEngines, SelectionKeepsTheRefereeAndAddsOutsideCcdEnginesOnly) {
  SuiteContext ctx;
  ctx.outside = loaded(testing::kExamplePlugin);
  ctx.engines = {"core", "sampled-ccd", "mt-plugin"};  // mt-plugin answers tri_tri only: not a ccd engine
  const auto engines = suite_engines(ctx);
  if (find_ccd_engine("exact")) {
    EXPECT_EQ(names(engines), (std::vector<std::string>{"core", "exact", "sampled-ccd"}));
  } else {
    EXPECT_EQ(names(engines), (std::vector<std::string>{"core", "sampled-ccd"}));
  }
  ctx.engines.clear();  // no --engines: every built-in engine, then sampled-ccd
  EXPECT_EQ(names(suite_engines(ctx)).back(), "sampled-ccd");
  EXPECT_EQ(suite_engines(ctx).size(), ccd_engines().size() + 1);
}

std::vector<KnownQuery> hand_block() {
  KnownQuery through;  // the vertex falls through a still triangle's interior at t = 1/2, a sample instant
  through.q.kind = CcdKind::VertexFace;
  through.q.x0 = {Vec3(0.25, 0.25, 1), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  through.q.x1 = {Vec3(0.25, 0.25, -1), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  KnownQuery cross;  // the edge (0..1, 0, z) falls through the still edge x = 1/2 at t = 1/2
  cross.q.kind = CcdKind::EdgeEdge;
  cross.q.x0 = {Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0.5, -1, 0), Vec3(0.5, 1, 0)};
  cross.q.x1 = {Vec3(0, 0, -1), Vec3(1, 0, -1), Vec3(0.5, -1, 0), Vec3(0.5, 1, 0)};
  return {through, cross};
}

TEST(CcdSuiteEngines, AnOutsideEngineAnswersTheKindsItModels) {
  SuiteContext ctx;
  ctx.engines = {"sampled-ccd"};
  double seconds = -1.0;
  ctx.outside = loaded(testing::kExamplePlugin);
  const auto full = named(suite_engines(ctx), "sampled-ccd");
  EXPECT_TRUE(full.models(CcdKind::VertexFace) && full.models(CcdKind::EdgeEdge));
  const auto a = answer_block(full, hand_block(), seconds);
  ASSERT_TRUE(a[0] && a[1]);
  EXPECT_TRUE(a[0]->hit && a[1]->hit);
  EXPECT_EQ(a[0]->toi, 0.5);  // the coplanarity is 0 at the sample t = 1/2 itself
  EXPECT_GE(seconds, 0.0);
  ctx.outside = loaded(testing::kLiarPlugin);
  const auto half = named(suite_engines(ctx), "sampled-ccd");
  EXPECT_TRUE(half.models(CcdKind::VertexFace));
  EXPECT_FALSE(half.models(CcdKind::EdgeEdge));
  const auto b = answer_block(half, hand_block(), seconds);
  ASSERT_TRUE(b[0]);
  EXPECT_TRUE(b[0]->hit);
  EXPECT_FALSE(b[1]);  // not modelled: no answer
}

}  // namespace
}  // namespace tecido::suites::ccd
