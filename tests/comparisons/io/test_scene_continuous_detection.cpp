// The scene key "self_collision":{"detection":"discrete"|"continuous",...} and the "impulse"
// response (comparisons/io/scene_json.cpp, core/cloth/self_collision_settings.h).
#include "comparisons/io/scene_json.h"

#include <gtest/gtest.h>

namespace tecido {
namespace {

std::string scene_with_detection(const std::string& self_collision) {
  return R"({"dt":0.01,"steps":10,
 "cloth":{"rows":4,"cols":4,"spacing":0.1,"origin":[0,0,0],"axis_u":[1,0,0],"axis_v":[0,1,0],
          "total_mass":0.1,"stiffness_b":5,"elasticity":0.5},
 "self_collision":)" + self_collision + "}";
}

Scene read(const std::string& text) { return io::scene_from_json(io::parse_json_text(text, "s.json"), "s.json"); }

std::string error_of(const std::string& text) {
  try {
    read(text);
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneContinuousDetection, DetectionDefaultsToDiscrete) {
  const Scene s = read(scene_with_detection(R"({"response":"edge3","strength":0.1})"));
  ASSERT_TRUE(s.self_collision);
  EXPECT_EQ(s.self_collision->detection, SelfCollisionDetection::Discrete);
}

TEST(SceneContinuousDetection, ContinuousDetectionWithEveryResponse) {
  const Scene s = read(scene_with_detection(R"({"detection":"continuous","response":"impulse","every":2})"));
  ASSERT_TRUE(s.self_collision);
  EXPECT_EQ(s.self_collision->detection, SelfCollisionDetection::Continuous);
  EXPECT_EQ(s.self_collision->response, SelfCollisionResponse::Impulse);
  EXPECT_EQ(s.self_collision->strength, 0.0);  // the impulse needs no force
  EXPECT_EQ(s.self_collision->every, 2);
  const Scene g = read(scene_with_detection(R"({"detection":"continuous","response":"gia+edge3","strength":0.5})"));
  EXPECT_EQ(g.self_collision->response, SelfCollisionResponse::GiaEdge3);
  EXPECT_EQ(g.self_collision->detection, SelfCollisionDetection::Continuous);
}

TEST(SceneContinuousDetection, RejectsImpulseWithoutContinuousDetectionAndUnknownNames) {
  struct Bad {
    std::string self_collision, where, problem;
  };
  const std::vector<Bad> bad = {
      {R"({"response":"impulse"})", "/self_collision/response", "needs \"detection\": \"continuous\""},
      {R"({"detection":"discrete","response":"impulse"})", "/self_collision/response", "needs \"detection\""},
      {R"({"detection":"ccd","response":"none"})", "/self_collision/detection", "unknown detection \"ccd\""},
      {R"({"detection":true,"response":"none"})", "/self_collision/detection", "expected a string"},
      {R"({"detection":"continuous","response":"edge1"})", "/self_collision/strength", "missing required key"},
  };
  for (const Bad& b : bad) {
    const std::string msg = error_of(scene_with_detection(b.self_collision));
    EXPECT_EQ(msg.rfind("s.json: " + b.where + ": ", 0), 0u) << b.self_collision << ": " << msg;
    EXPECT_NE(msg.find(b.problem), std::string::npos) << msg;
  }
}

}  // namespace
}  // namespace tecido
