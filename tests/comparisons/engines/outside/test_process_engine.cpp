// The Python example and the misbehaving fixture through ProcessEngine: hello, the example's edge
// test on hand-worked pairs (batched and one by one agree; 4097 pairs take two batched round
// trips), its midpoint step against a hand-worked step, refusals, the scene lease, and every door
// failure as one EngineError naming the engine, its command, the request and its stderr tail.
#include "comparisons/engines/outside/engine_error.h"
#include "comparisons/engines/outside/process_engine.h"
#include "tests/support/outside_fixtures.h"

#include <gtest/gtest.h>

#include <chrono>

namespace tecido::outside {
namespace {

using namespace std::chrono_literals;

std::shared_ptr<ProcessEngine> python(std::chrono::duration<double> timeout = 30s) {
  return ProcessEngine::start("py", testing::kPythonEngine, timeout);
}

std::vector<TriTriQuery> hand_queries() {
  std::vector<TriTriQuery> qs;
  for (const auto& p : testing::hand_pairs()) qs.push_back({p.a, p.b});
  return qs;
}

TEST(ProcessEngine, HelloOfThePythonExample) {
  const auto e = python();
  EXPECT_TRUE(e->capabilities().tri_tri);
  EXPECT_TRUE(e->capabilities().dynamics);
  EXPECT_TRUE(e->capabilities().ccd_vertex_face);
  EXPECT_TRUE(e->capabilities().ccd_edge_edge);
  EXPECT_FALSE(e->capabilities().segment_plane);
  EXPECT_EQ(e->claimed_order(), 2.0);
  EXPECT_TRUE(e->is_process());
  EXPECT_EQ(e->door(), "process `" + testing::kPythonEngine + "`");
  EXPECT_EQ(e->round_trips(), 1);
}

TEST(ProcessEngine, CcdQueriesGoInOneBatch) {
  const auto e = python();
  // A vertex falling through a still triangle's interior at t = 1/2, and the same vertex beside it.
  CcdQuery through;
  through.kind = CcdKind::VertexFace;
  through.x0 = {Vec3(0.25, 0.25, 1), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  through.x1 = {Vec3(0.25, 0.25, -1), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  CcdQuery beside = through;
  beside.x0[0] = Vec3(2, 2, 1);
  beside.x1[0] = Vec3(2, 2, -1);
  const long long before = e->round_trips();
  const auto answers = e->ccd({through, beside, through});
  EXPECT_EQ(e->round_trips(), before + 1);  // hello lists ccd_batch
  ASSERT_EQ(answers.size(), 3u);
  ASSERT_TRUE(answers[0] && answers[1] && answers[2]);
  EXPECT_TRUE(answers[0]->hit);
  EXPECT_NEAR(answers[0]->toi, 0.5, 1e-12);
  EXPECT_FALSE(answers[1]->hit);
  EXPECT_TRUE(answers[2]->hit);
}

TEST(ProcessEngine, EdgeTestOnHandWorkedPairs) {
  const auto e = python();
  const auto answers = e->tri_tri(hand_queries());
  for (std::size_t k = 0; k < answers.size(); ++k) {
    ASSERT_TRUE(answers[k]);
    EXPECT_EQ(*answers[k], testing::hand_pairs()[k].edges) << testing::hand_pairs()[k].id;
  }
}

TEST(ProcessEngine, BatchesInChunks) {
  const auto e = python();
  std::vector<TriTriQuery> qs;
  const auto hand = hand_queries();
  for (std::size_t k = 0; k < ProcessEngine::kBatchChunk + 1; ++k) qs.push_back(hand[k % hand.size()]);
  const long long before = e->round_trips();
  const auto answers = e->tri_tri(qs);
  EXPECT_EQ(e->round_trips() - before, 2);  // 4096 + 1
  ASSERT_EQ(answers.size(), qs.size());
  for (std::size_t k = 0; k < qs.size(); ++k) EXPECT_EQ(*answers[k], testing::hand_pairs()[k % hand.size()].edges);
}

TEST(ProcessEngine, UnbatchedEngineTakesOneRoundTripPerQuery) {
  const auto e = ProcessEngine::start("m", testing::misbehaving_engine("none"), 30s);
  const long long before = e->round_trips();
  const auto answers = e->tri_tri(hand_queries());
  EXPECT_EQ(e->round_trips() - before, static_cast<long long>(hand_queries().size()));
  for (const auto& a : answers) EXPECT_EQ(a, false);
}

TEST(ProcessEngine, MidpointOneStepByHand) {
  // One particle, m = 2, v = (1, 0, 0), gravity (0, 0, -2), drag c = 1: a(v) = g - (c/m) v.
  Scene s;
  s.dt = 0.5;
  s.particles.add(Vec3::Zero(), Vec3(1, 0, 0), 2.0, 1.0, false);
  s.forces.gravity = Vec3(0, 0, -2);
  s.forces.air_drag = 1.0;
  Creation c = python()->create(s);
  ASSERT_TRUE(c.simulation) << c.refusal;
  ASSERT_TRUE(c.simulation->step());
  // a0 = (-0.5, 0, -2); v_mid = v + h/2 a0 = (0.875, 0, -0.5); a_mid = (-0.4375, 0, -1.75);
  // x1 = h v_mid = (0.4375, 0, -0.25); v1 = v + h a_mid = (0.78125, 0, -0.875).
  EXPECT_EQ(c.simulation->positions()[0], Vec3(0.4375, 0, -0.25));
  EXPECT_EQ(c.simulation->velocities()[0], Vec3(0.78125, 0, -0.875));
}

TEST(ProcessEngine, RefusalIsTheEnginesReason) {
  Scene s;
  s.particles.add(Vec3::Zero(), Vec3::Zero(), 1.0, 1.0, false);
  s.planes.push_back(BoundedPlane{});
  const auto e = python();
  Creation c = e->create(s);
  EXPECT_FALSE(c.simulation);
  EXPECT_EQ(c.refusal, "not modelled: planes");
  // The lease was returned: a scene it models can be created next.
  s.planes.clear();
  EXPECT_TRUE(e->create(s).simulation);
}

TEST(ProcessEngine, OneSceneAtATimePerThread) {
  Scene s;
  s.particles.add(Vec3::Zero(), Vec3::Zero(), 1.0, 1.0, false);
  const auto e = python();
  Creation first = e->create(s);
  ASSERT_TRUE(first.simulation);
  try {
    e->create(s);
    FAIL() << "a second simulation on the same thread must be refused";
  } catch (const EngineError& err) {
    EXPECT_NE(std::string(err.what()).find("one scene at a time"), std::string::npos) << err.what();
  }
  first.simulation.reset();
  EXPECT_TRUE(e->create(s).simulation);
}

std::string step_error(const std::string& mode, std::chrono::duration<double> timeout = 30s) {
  Scene s;
  s.particles.add(Vec3::Zero(), Vec3::Zero(), 1.0, 1.0, false);
  try {
    Creation c = ProcessEngine::start("bad", testing::misbehaving_engine(mode), timeout)->create(s);
    c.simulation->advance(10);
  } catch (const EngineError& e) {
    return e.what();
  }
  return "";
}

TEST(ProcessEngine, DeathNamesEngineCommandOpAndStderr) {
  const std::string e = step_error("die-at-step");
  EXPECT_NE(e.find("engine bad (`" + testing::misbehaving_engine("die-at-step") + "`): op step:"), std::string::npos) << e;
  EXPECT_NE(e.find("exited with status 3"), std::string::npos) << e;
  EXPECT_NE(e.find("its stderr ends: boom: integrator diverged"), std::string::npos) << e;
}

TEST(ProcessEngine, HangIsATimeout) {
  const std::string e = step_error("hang-at-step", 500ms);
  EXPECT_NE(e.find("op step: no reply within 0.5 s"), std::string::npos) << e;
}

TEST(ProcessEngine, GarbageIsMalformedJson) {
  const std::string e = step_error("garbage-at-step");
  EXPECT_NE(e.find("op step: malformed JSON reply: \"this is not json\""), std::string::npos) << e;
}

// A number past the range of doubles is valid JSON that nlohmann/json refuses with out_of_range
// (406), not parse_error: still the door's one EngineError (fuzz_engine_replies' regress_toi_overflow).
TEST(ProcessEngine, NumberPastTheDoubleRangeIsAnEngineError) {
  const std::string e = step_error("overflow-at-step");
  EXPECT_NE(e.find("op step: a number in the reply is out of the range of doubles: \"{\"x\": [[1e400"), std::string::npos)
      << e;
}

TEST(ProcessEngine, WrongStateSizeIsAProtocolError) {
  const std::string e = step_error("short-step");
  EXPECT_NE(e.find("op step: \"x\" must be an array of 1 points"), std::string::npos) << e;
}

TEST(ProcessEngine, HelloFailures) {
  const auto start_error = [](const std::string& cmd) {
    try {
      ProcessEngine::start("h", cmd, 2s);
    } catch (const EngineError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(start_error("read -r l; echo '{\"supports\":\"all\"}'").find("op hello: \"supports\" must be an array"), std::string::npos);
  EXPECT_NE(start_error("read -r l; echo '{\"supports\":[\"teleport\"]}'").find("lists none of"), std::string::npos);
  EXPECT_NE(start_error("read -r l; echo '[]'").find("op hello: the reply is not a JSON object"), std::string::npos);
}

}  // namespace
}  // namespace tecido::outside
