// The sheet-through-sheet case group (comparisons/suites/ccd/sheet_through_sheet.h): a sheet
// passing through another within one step. Discrete detection sees nothing and, without a
// response, the sheet passes through; continuous detection finds exactly the referee's contacts;
// continuous detection with the impulse response keeps the sheets apart at every step, checked
// by the exact referee between consecutive frames.
#include "comparisons/suites/ccd/sheet_through_sheet.h"

#include "core/simulation/self_collision_response.h"
#include "core/simulation/simulation.h"

#include <gtest/gtest.h>

namespace tecido::suites::ccd {
namespace {

SheetSettings small() {
  SheetSettings s;
  s.n = 6;
  s.steps = 5;
  return s;
}

TEST(SheetThroughSheet, FramesHaveNoIntersectionButTheStepPassesThrough) {
  const SheetScene sc = sheet_through_sheet_scene(small());
  ASSERT_GT(sc.first_b, 0);
  // B is entirely above A's plane in the first frame and entirely below it in the second.
  for (std::size_t i = static_cast<std::size_t>(sc.first_b); i < sc.x0.size(); ++i) {
    EXPECT_GT(sc.x0[i].z(), 0.0);
    EXPECT_LT(sc.x1[i].z(), 0.0);
    EXPECT_NEAR(((sc.x1[i] - sc.x0[i]) / sc.scene.dt - sc.scene.particles.v[i]).norm(), 0.0, 1e-9);
  }
  for (int i = 0; i < sc.first_b; ++i) EXPECT_EQ(sc.x0[i].z(), 0.0);
}

TEST(SheetThroughSheet, ContinuousDetectionWithoutResponseSeesWhatDiscreteMisses) {
  const SheetScene sc = sheet_through_sheet_scene(small());
  for (const auto detection : {SelfCollisionDetection::Discrete, SelfCollisionDetection::Continuous}) {
    Scene scene = sc.scene;
    scene.self_collision = SelfCollisionSettings{};
    scene.self_collision->detection = detection;
    Simulation sim(scene);
    const auto hook = install_self_collision(sim);
    ASSERT_TRUE(sim.step());
    const bool continuous = detection == SelfCollisionDetection::Continuous;
    EXPECT_EQ(hook->stats().contact_checks, continuous ? 1 : 0);
    if (continuous) {
      EXPECT_GT(hook->last_contacts().vertex_face.size(), 0u);
    }
  }
}

TEST(SheetThroughSheet, PairResponsesGetTheContactsTriangles) {
  // Continuous detection feeds the edge modes every contact's triangles; GIA only those that
  // intersect at the end of the step, and after a full pass-through none does.
  const SheetScene sc = sheet_through_sheet_scene(small());
  for (const auto response : {SelfCollisionResponse::Edge2, SelfCollisionResponse::Gia}) {
    Scene scene = sc.scene;
    scene.self_collision = SelfCollisionSettings{};
    scene.self_collision->detection = SelfCollisionDetection::Continuous;
    scene.self_collision->response = response;
    scene.self_collision->strength = 0.1;
    Simulation sim(scene);
    const auto hook = install_self_collision(sim);
    ASSERT_TRUE(sim.step());
    EXPECT_EQ(hook->stats().contact_checks, 1);
    if (response == SelfCollisionResponse::Edge2) {
      EXPECT_GT(hook->last_pairs().size(), 0u);
      for (const auto& p : hook->last_pairs()) {
        EXPECT_LT(p[0], p[1]);
        EXPECT_LT(p[0], static_cast<int>(scene.triangles.size()) / 2);  // one triangle of each sheet
        EXPECT_GE(p[1], static_cast<int>(scene.triangles.size()) / 2);
      }
      EXPECT_GT(hook->stats().pushed_particles, 0);
    } else {
      EXPECT_EQ(hook->last_pairs().size(), 0u);
      EXPECT_EQ(hook->stats().gia_regions, 0);
    }
  }
}

TEST(SheetThroughSheet, CoreMatchesTheRefereeAndTheImpulseKeepsTheSheetsApart) {
  const SheetResult r = run_sheet_through_sheet(small());
  EXPECT_EQ(r.discrete_pairs, 0);
  EXPECT_EQ(r.discrete_run_contacts, 0);
  EXPECT_EQ(r.discrete_passed, 1);
  EXPECT_GT(r.exact_contacts, 10);
  EXPECT_EQ(r.core_contacts, r.exact_contacts);
  EXPECT_EQ(r.core_missed, 0);
  EXPECT_EQ(r.core_extra, 0);
  EXPECT_EQ(r.candidates_differ, 0);
  EXPECT_EQ(r.brute_missed, 0);
  EXPECT_EQ(r.impulse_steps, small().steps);
  EXPECT_EQ(r.impulse_contacts, 0);
}

}  // namespace
}  // namespace tecido::suites::ccd
