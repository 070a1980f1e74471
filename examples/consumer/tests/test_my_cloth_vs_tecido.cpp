// The user's cloth integrator against tecido's engine (tecido/simulation.h) on the same scene, step
// for step, and tecido's cloth dropped on a floor as a user would set it up. docs/package.md shows
// the first test as its example.
#include "my_engine.h"

#include <gtest/gtest.h>
#include <tecido/simulation.h>

#include <algorithm>
#include <cstdint>
#include <iostream>
#include <vector>

namespace {

namespace tc = tecido::core;
using tecido::Vec3;

// docs/package.md: "A scene in code"
tc::Scene hanging_cloth() {
  tc::ClothGrid cloth;
  cloth.rows = cloth.cols = 8;
  cloth.spacing = 0.05;                  // [m]
  cloth.axis_v = Vec3::UnitY();          // horizontal: it drapes as it falls
  cloth.total_mass = 0.2;                // [kg]
  cloth.stiffness = 50.0;                // [N/m], one edge apart
  cloth.bend_stiffness = 10.0;           // two edges apart
  cloth.pins = {{0, 0}, {0, 7}};         // the top corners
  tc::Scene scene;
  scene.set_integrator(tc::Integrator::Symplectic).set_dt(1e-3).set_gravity(Vec3(0, 0, -9.81));
  scene.add_cloth(cloth);
  return scene;
}

TEST(MyClothVsTecido, SymplecticEulerStepForStep) {
  const tc::Scene scene = hanging_cloth();
  tc::Simulation tecido_run(scene);
  tecido_run.run(500);
  ASSERT_FALSE(tecido_run.diverged());

  // The same scene for my engine, through the plug-in ABI's scene.
  std::vector<double> x, v;
  for (std::size_t p = 0; p < scene.particle_count(); ++p)
    for (int k = 0; k < 3; ++k) x.push_back(scene.positions()[p][k]), v.push_back(scene.velocities()[p][k]);
  std::vector<std::uint32_t> ends;
  std::vector<double> stiffness, rest;
  for (const tc::SpringInfo& s : scene.springs()) {
    ends.push_back(static_cast<std::uint32_t>(s.i));
    ends.push_back(static_cast<std::uint32_t>(s.j));
    stiffness.push_back(s.stiffness);
    rest.push_back(s.rest_length);
  }
  tecido_scene mine{};
  mine.particle_count = scene.particle_count();
  mine.positions = x.data();
  mine.velocities = v.data();
  mine.inverse_masses = scene.inverse_masses().data();
  mine.spring_count = stiffness.size();
  mine.spring_ends = ends.data();
  mine.spring_stiffness = stiffness.data();
  mine.spring_rest_length = rest.data();
  for (int k = 0; k < 3; ++k) mine.gravity[k] = scene.gravity()[k];
  mine.dt = scene.dt();
  char why[256] = "";
  void* sim = my_cloth_create(&mine, why, sizeof why);
  ASSERT_NE(sim, nullptr) << why;
  ASSERT_EQ(my_cloth_step(sim, scene.dt(), 500), 0);
  my_cloth_read(sim, x.data(), v.data());
  my_cloth_destroy(sim);

  // The same method on the same numbers: only the order of the force sums differs.
  double worst = 0.0;
  for (std::size_t p = 0; p < scene.particle_count(); ++p)
    worst = std::max(worst, (Vec3(x[3 * p], x[3 * p + 1], x[3 * p + 2]) - tecido_run.positions()[p]).norm());
  std::cout << "largest distance from tecido's positions after 500 steps: " << worst << " m\n";
  EXPECT_LT(worst, 1e-9);
  // And it moved (the comparison is of a swinging cloth, not of one at rest).
  double moved = 0.0;
  for (std::size_t p = 0; p < scene.particle_count(); ++p)
    moved = std::max(moved, (tecido_run.positions()[p] - scene.positions()[p]).norm());
  std::cout << "largest distance moved: " << moved << " m\n";
  EXPECT_GT(moved, 0.01);
}

TEST(TecidoCloth, DroppedOnAFloorNeverGoesThroughIt) {
  tc::ClothGrid cloth;
  cloth.rows = cloth.cols = 10;
  cloth.spacing = 0.05;
  cloth.origin = Vec3(-0.225, -0.225, 0.3);
  cloth.stiffness = 200.0;
  cloth.damping = 0.02;
  cloth.elasticity = 0.2;
  tc::Scene scene;
  scene.set_integrator(tc::Integrator::RK4).set_dt(2e-3).set_gravity(Vec3(0, 0, -9.81));
  scene.add_cloth(cloth);
  tecido::Rectangle floor;  // z = 0, 2 m x 2 m
  scene.add_plane(floor, 0.5);
  tc::Sphere bump;
  bump.center = Vec3(0, 0, 0);
  bump.radius = 0.1;
  scene.add_sphere(bump);
  tc::Simulation sim(scene);
  for (int step = 0; step < 1000; ++step) {
    ASSERT_TRUE(sim.step());
    for (const Vec3& p : sim.positions()) {
      ASSERT_GE(p.z(), 0.0) << "step " << sim.steps_done();          // above the floor
      ASSERT_GE(p.squaredNorm(), bump.radius * bump.radius) << "step " << sim.steps_done();  // outside the sphere
    }
  }
  EXPECT_GT(sim.contacts().events, 0);
  EXPECT_GT(sim.contacts().obstacle_contacts, 0);
}

}  // namespace
