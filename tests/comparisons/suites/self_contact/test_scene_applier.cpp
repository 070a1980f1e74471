// comparisons/suites/self_contact/scene_applier.h and run.h on the experiment's own scene: what a
// cell and a reading change (checked against the base scene's numbers), what the base scene must
// be, and that counting never changes a run.
#include "comparisons/io/source_dir.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/scene_json.h"
#include "comparisons/suites/self_contact/run.h"
#include "comparisons/suites/self_contact/scene_applier.h"

#include <gtest/gtest.h>

namespace tecido::suites::self_contact {
namespace {

const std::string kScene = std::string(TECIDO_SOURCE_DIR) + "/data/scenes/seed_fig21_self_contact.json";

TEST(SceneApplier, ACellAndAReadingSetWhatTheyName) {
  const Scene base = io::load_scene(kScene);
  ASSERT_NO_THROW(check_base_scene(base, kScene));
  Interpretation in = scene_interpretation(base);
  in.air_drag = 0.03;
  in.swirl_rate = 1.1;
  in.heading_diffusion = 0.25;
  const Cell cell = CellGrid::cell(CellGrid::index({2, 1, 1, 2}));  // 0.11 N, 0.01 s, e 0.5, mode 2
  const Scene s = apply_cell(base, cell, in, 99, 3.0);
  EXPECT_EQ(s.dt, 0.01);
  EXPECT_EQ(s.steps, 300);
  EXPECT_EQ(*s.forces.air_drag, 0.03);
  const Wind& w = *s.forces.wind;
  EXPECT_NEAR(w.force.norm(), 0.11, 1e-15);
  EXPECT_NEAR(w.force.normalized().dot(base.forces.wind->force.normalized()), 1.0, 1e-15);
  EXPECT_EQ(w.rate, 1.1);
  EXPECT_EQ(w.random->seed, 99u);
  EXPECT_EQ(w.random->diffusion, 0.25);
  EXPECT_GE(w.random->knots.size(), 31u);  // prepared for 3 s at 0.1 s
  ASSERT_EQ(s.forces.springs.size(), base.forces.springs.size());
  for (std::size_t k = 0; k < s.forces.springs.size(); ++k)
    EXPECT_EQ(s.forces.springs[k].stiffness, base.forces.springs[k].stiffness * 0.5) << k;
  EXPECT_EQ(s.self_collision->response, SelfCollisionResponse::Edge2);
  EXPECT_EQ(s.self_collision->every, 1);
  EXPECT_EQ(s.particles.inv_mass, base.particles.inv_mass);
}

TEST(SceneApplier, AlternativeReadings) {
  const Scene base = io::load_scene(kScene);
  Interpretation in = scene_interpretation(base);
  in.elasticity_as = "restitution";
  in.wind_per = "total";
  in.pins = {{0, 0}, {0, 15}};
  const Cell cell = CellGrid::cell(CellGrid::index({0, 0, 1, 0}));  // 0.09 N, e 0.5, no response
  const Scene s = apply_cell(base, cell, in, 1, 1.0);
  for (std::size_t k = 0; k < s.forces.springs.size(); ++k)
    EXPECT_EQ(s.forces.springs[k].stiffness, base.forces.springs[k].stiffness) << k;
  for (double e : s.particles.elasticity) EXPECT_EQ(e, 0.5);
  int pinned = 0;
  for (auto p : s.particles.pinned) pinned += p;
  EXPECT_EQ(pinned, 2);
  EXPECT_EQ(s.particles.inv_mass[0], 0.0);
  EXPECT_GT(s.particles.inv_mass[3], 0.0);  // pinned in the base scene, free here
  EXPECT_NEAR(s.forces.wind->force.norm(), 0.09 / (256 - 2), 1e-17);
  EXPECT_EQ(s.self_collision->response, SelfCollisionResponse::None);
  in.wind_per = "nonsense";
  EXPECT_THROW(apply_cell(base, cell, in, 1, 1.0), io::UsageError);
}

TEST(SceneApplier, BaseSceneMustBeAClothInARandomWind) {
  Scene base = io::load_scene(kScene);
  Scene extra = base;
  extra.particles.add(Vec3(5, 5, 5), Vec3::Zero(), 1.0, 0.5, false);
  EXPECT_THROW(check_base_scene(extra, "x.json"), io::InputError);
  Scene calm = base;
  calm.forces.wind->random.reset();
  EXPECT_THROW(check_base_scene(calm, "x.json"), io::InputError);
  Scene plain = base;
  plain.self_collision.reset();
  EXPECT_THROW(check_base_scene(plain, "x.json"), io::InputError);
}

TEST(Run, CountingDoesNotChangeTheRunAndFramesAreSteps) {
  const Scene base = io::load_scene(kScene);
  const Scene s = apply_cell(base, CellGrid::cell(CellGrid::index({1, 0, 0, 3})), scene_interpretation(base), 5, 4.0);
  const RunResult one = run_scene(s, {ContactTest::Core}, true);
  const RunResult both = run_scene(s, {ContactTest::CoreMt, ContactTest::Core, ContactTest::CoreRotation}, true);
  ASSERT_EQ(both.counts.size(), 3u);
  EXPECT_EQ(one.counts[0].frames, s.steps);
  EXPECT_EQ(both.counts[1].frames, s.steps);
  EXPECT_EQ(both.counts[1].contact_frames, one.counts[0].contact_frames);
  EXPECT_EQ(both.counts[1].pairs, one.counts[0].pairs);
  EXPECT_EQ(both.premise.contact_frames, one.counts[0].contact_frames);  // the premise looks at exact contacts
  EXPECT_LE(both.premise.border_frames, both.premise.contact_frames);
  const RunResult back = run_from_json(run_json(both, true));
  EXPECT_EQ(back.counts[2].max_pairs, both.counts[2].max_pairs);
  EXPECT_EQ(back.premise.unresolved_frames, both.premise.unresolved_frames);
  EXPECT_EQ(share(back, 0), static_cast<double>(both.counts[0].contact_frames) / s.steps);
}

}  // namespace
}  // namespace tecido::suites::self_contact
