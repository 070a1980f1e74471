// A Scene as the plug-in ABI's flat arrays, and the feature bits an engine must model or refuse.
#include "comparisons/engines/outside/scene_arrays.h"
#include "comparisons/engines/outside/scene_features.h"

#include <gtest/gtest.h>

namespace tecido::outside {
namespace {

Scene two_particles() {
  Scene s;
  s.dt = 0.125;
  s.particles.add(Vec3(1, 2, 3), Vec3(4, 5, 6), 0.0, 1.0, true);
  s.particles.add(Vec3(7, 8, 9), Vec3(-1, -2, -3), 4.0, 1.0, false);
  s.forces.springs.push_back(Spring{1, 0, 10.0, 0.5, 0.0});
  return s;
}

TEST(SceneArrays, FlatInParticleOrder) {
  Scene s = two_particles();
  s.forces.gravity = Vec3(0, 0, -9.81);
  s.forces.air_drag = 0.25;
  const SceneArrays a = scene_arrays(s);
  EXPECT_EQ(a.positions, (std::vector<double>{1, 2, 3, 7, 8, 9}));
  EXPECT_EQ(a.velocities, (std::vector<double>{0, 0, 0, -1, -2, -3}));  // a pinned particle's velocity is 0
  EXPECT_EQ(a.inverse_masses, (std::vector<double>{0.0, 0.25}));
  EXPECT_EQ(a.spring_ends, (std::vector<std::uint32_t>{1, 0}));
  EXPECT_EQ(a.spring_stiffness, (std::vector<double>{10.0}));
  EXPECT_EQ(a.spring_rest_length, (std::vector<double>{0.5}));
  const tecido_scene v = a.view();
  EXPECT_EQ(v.particle_count, 2u);
  EXPECT_EQ(v.spring_count, 1u);
  EXPECT_EQ(v.gravity[2], -9.81);
  EXPECT_EQ(v.linear_drag, 0.25);
  EXPECT_EQ(v.dt, 0.125);
  EXPECT_EQ(v.features, 0u);
  EXPECT_EQ(v.positions[4], 8.0);
}

TEST(SceneArrays, AbsentGravityAndDragAreZero) {
  const tecido_scene v = scene_arrays(two_particles()).view();
  EXPECT_EQ(v.gravity[0], 0.0);
  EXPECT_EQ(v.gravity[2], 0.0);
  EXPECT_EQ(v.linear_drag, 0.0);
}

TEST(SceneFeatures, EachFeatureItsBit) {
  Scene s = two_particles();
  EXPECT_EQ(feature_bits(s), 0u);
  s.forces.wind = Wind{};
  EXPECT_EQ(feature_bits(s), TECIDO_FEATURE_WIND);
  s.planes.push_back(BoundedPlane{});
  s.forces.springs[0].damping = 0.1;
  EXPECT_EQ(feature_bits(s), TECIDO_FEATURE_WIND | TECIDO_FEATURE_PLANES | TECIDO_FEATURE_SPRING_DAMPING);
  s.self_collision = SelfCollisionSettings{};
  EXPECT_EQ(feature_bits(s) & TECIDO_FEATURE_SELF_COLLISION, TECIDO_FEATURE_SELF_COLLISION);
  EXPECT_EQ(feature_names(feature_bits(s)),
            (std::vector<std::string>{"wind", "planes", "spring_damping", "self_collision"}));
  EXPECT_EQ(feature_names(std::uint64_t(1) << 40), (std::vector<std::string>{"feature-bit-40"}));
}

}  // namespace
}  // namespace tecido::outside
