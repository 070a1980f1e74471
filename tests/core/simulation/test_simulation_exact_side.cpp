// The simulation's side bookkeeping uses the exact side sign: a step that ends exactly on a
// tilted plane, where the rounded side still says "strictly on its side", is a contact in that
// very step (the rounded prefilter skipped it and found the contact one step late).
#include "core/simulation/simulation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido {
namespace {

TEST(SimulationExactSide, AStepEndingExactlyOnATiltedPlaneIsAContact) {
  // Normal (k, k, k), k = 1/sqrt(3) rounded; forward (1, -1, 0)/sqrt(2). The end point x1 has
  // x + y + z = 0 exactly, so it lies exactly on the plane through the origin, while the rounded
  // side n.x1 is about -1.7e-17: "strictly below", the side the particle comes from.
  const double k = 1.0 / std::sqrt(3.0);
  const BoundedPlane pl = make_bounded_plane(Vec3::Zero(), Vec3(k, k, k), Vec3(1, -1, 0) / std::sqrt(2.0), Vec2(10, 10), 0.0);
  ASSERT_EQ(pl.normal, Vec3(k, k, k));  // kept as given (unit within 1e-14)
  const Vec3 x1(1 + 0x1p-52, -1, -0x1p-52);
  const Vec3 x0(x1.x(), x1.y(), -0.5 - 0x1p-52);  // x + y + z = -0.5: below; x0 + 1 * v = x1 exactly
  const Vec3 v(0, 0, 0.5);
  ASSERT_EQ(x0 + 1.0 * v, x1);
  ASSERT_LT(pl.side(x1), 0.0) << "the trap: the rounded side is strictly negative";

  Scene s;
  s.integrator = IntegratorKind::Symplectic;
  s.dt = 1.0;
  s.particles.add(x0, v, 1.0, 0.5, false);
  s.planes.push_back(pl);
  Simulation sim(s);
  sim.set_log_contacts(true);
  ASSERT_TRUE(sim.step());
  ASSERT_EQ(sim.contact_log().size(), 1u);
  EXPECT_EQ(sim.contact_log().front().step, 1);
  EXPECT_EQ(sim.contact_log().front().kind, ContactKind::Elastic);
  // Bounced back: the next steps stay on the side it came from (n.x <= 0 exactly means
  // x + y + z <= 0, checked here in the rounded sum, which is exact for these coordinates only
  // if it is not close to 0; the particle moves away by about 0.25 per step).
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(sim.step());
    const Vec3& x = sim.particles().x[0];
    EXPECT_LT(x.x() + x.y() + x.z(), -0.1);
  }
}

}  // namespace
}  // namespace tecido
