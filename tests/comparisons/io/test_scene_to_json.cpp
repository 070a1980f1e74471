// A Scene written in tecido's scene format reads back as the same scene (scene_from_json): the
// particles, springs, forces and planes bit for bit; a cloth expanded into particles and springs.
#include "comparisons/io/scene_json.h"
#include "comparisons/io/scene_to_json.h"

#include <gtest/gtest.h>

namespace tecido::io {
namespace {

TEST(SceneToJson, RoundTripsThroughTheReader) {
  Scene s;
  s.integrator = IntegratorKind::RK4;
  s.dt = 0.1 / 3;  // not a short decimal: must round-trip exactly
  s.steps = 7;
  s.seed = 99;
  s.particles.add(Vec3(0.1, 0.2, 0.3), Vec3(1.0 / 3, 0, 0), 3.0, 0.5, false);
  s.particles.add(Vec3(1, 0, 0), Vec3::Zero(), 0.0, 0.25, true);
  s.forces.springs.push_back(Spring{0, 1, 4.0, 0.9, 0.125});
  s.forces.gravity = Vec3(0, 0, -9.81);
  s.forces.air_drag = 0.05;
  Wind w;
  w.force = Vec3(0.1, 0, 0);
  w.swirl = true;
  w.rate = 2.0;
  w.phase = 0.7;
  s.forces.wind = w;
  BoundedPlane p;
  p.position = Vec3(0, 0, -1);
  p.half_extents = Vec2(2, 3);
  p.friction = 0.5;
  s.planes.push_back(p);

  const Scene r = scene_from_json(scene_to_json(s), "written");
  EXPECT_EQ(r.integrator, IntegratorKind::RK4);
  EXPECT_EQ(r.dt, s.dt);
  EXPECT_EQ(r.steps, 7);
  EXPECT_EQ(r.seed, 99u);
  ASSERT_EQ(r.particles.size(), 2u);
  EXPECT_EQ(r.particles.x, s.particles.x);
  EXPECT_EQ(r.particles.v, s.particles.v);
  EXPECT_EQ(r.particles.pinned, s.particles.pinned);
  EXPECT_EQ(r.particles.elasticity, s.particles.elasticity);
  EXPECT_EQ(r.particles.inv_mass[1], 0.0);
  EXPECT_NEAR(r.particles.inv_mass[0], 1.0 / 3.0, 1e-16);  // the file holds the mass, 1 / inv_mass
  ASSERT_EQ(r.forces.springs.size(), 1u);
  EXPECT_EQ(r.forces.springs[0].rest_length, 0.9);
  EXPECT_EQ(r.forces.springs[0].damping, 0.125);
  EXPECT_EQ(*r.forces.gravity, *s.forces.gravity);
  EXPECT_EQ(*r.forces.air_drag, 0.05);
  ASSERT_TRUE(r.forces.wind);
  EXPECT_TRUE(r.forces.wind->swirl);
  EXPECT_EQ(r.forces.wind->phase, 0.7);
  EXPECT_EQ(r.forces.wind->at(1.5), s.forces.wind->at(1.5));
  ASSERT_EQ(r.planes.size(), 1u);
  EXPECT_EQ(r.planes[0].position, p.position);
  EXPECT_EQ(r.planes[0].half_extents, p.half_extents);
  EXPECT_EQ(r.planes[0].friction, 0.5);
}

TEST(SceneToJson, ClothIsWrittenExpanded) {
  const Scene cloth = scene_from_json(
      Json::parse(R"({"dt":0.01,"steps":1,"cloth":{"rows":3,"cols":4,"spacing":0.1,"origin":[0,0,0],
        "axis_u":[1,0,0],"axis_v":[0,1,0],"total_mass":1.2,"stiffness_b":10,"stiffness_a":5,"damping":0,"elasticity":0.5}})"),
      "cloth");
  const Json j = scene_to_json(cloth);
  EXPECT_FALSE(j.contains("cloth"));
  EXPECT_EQ(j["particles"].size(), 12u);
  const Scene r = scene_from_json(j, "written");
  EXPECT_EQ(r.particles.x, cloth.particles.x);
  ASSERT_EQ(r.forces.springs.size(), cloth.forces.springs.size());
  for (std::size_t k = 0; k < r.forces.springs.size(); ++k) {
    EXPECT_EQ(r.forces.springs[k].i, cloth.forces.springs[k].i);
    EXPECT_EQ(r.forces.springs[k].rest_length, cloth.forces.springs[k].rest_length);
  }
}

}  // namespace
}  // namespace tecido::io
