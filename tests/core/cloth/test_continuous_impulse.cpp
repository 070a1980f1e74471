// core/cloth/continuous_impulse.h: the inelastic impulse at the time of impact, on hand-worked
// contacts (the kept gap, the weights, momentum) and the corrected motion's own answer.
#include "core/cloth/continuous_impulse.h"

#include "core/geometry/ccd/ccd.h"

#include <gtest/gtest.h>

namespace tecido {
namespace {

const std::vector<std::array<int, 3>> kTri = {{1, 2, 3}};

/// Vertex 0 from (1/4, 1/4, 1) to (1/4, 1/4, -1) through the triangle (0,0,0), (1,0,0), (0,1,0) at
/// rest, over h = 0.1 s; velocities are the average ones.
struct Fall {
  std::vector<Vec3> x0 = {Vec3(0.25, 0.25, 1), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  std::vector<Vec3> x1 = {Vec3(0.25, 0.25, -1), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  std::vector<Vec3> v = {Vec3(0, 0, -20), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  double h = 0.1;
  ContinuousContacts contacts() const {
    ContinuousContacts c;
    c.vertex_face = {{0, 0}};
    return c;
  }
};

TEST(ContinuousImpulse, VertexOnAPinnedTriangleKeepsHalfItsGap) {
  Fall f;
  const std::vector<double> inv_mass = {1.0, 0.0, 0.0, 0.0};
  EXPECT_EQ(apply_contact_impulses(f.contacts(), kTri, f.x0, f.x1, f.v, inv_mass, f.h), 1);
  // Gap 1 at the start along n = +z; kept: 1/2, so the vertex ends at z = 1/2 moving at -5 m/s.
  EXPECT_NEAR(f.x1[0].z(), 0.5, 1e-12);
  EXPECT_NEAR(f.v[0].z(), -5.0, 1e-12);
  EXPECT_EQ(f.x1[0].head<2>(), Vec2(0.25, 0.25));
  for (int i = 1; i < 4; ++i) EXPECT_EQ(f.v[i], Vec3::Zero());
  // The corrected motion no longer touches.
  CcdQuery q;
  q.kind = CcdKind::VertexFace;
  for (int i = 0; i < 4; ++i) q.x0[i] = f.x0[i], q.x1[i] = f.x1[i];
  EXPECT_FALSE(ccd(q).hit);
}

TEST(ContinuousImpulse, FreeTriangleSharesTheImpulseByWeightsAndKeepsMomentum) {
  Fall f;
  const std::vector<double> inv_mass = {1.0, 1.0, 1.0, 1.0};
  apply_contact_impulses(f.contacts(), kTri, f.x0, f.x1, f.v, inv_mass, f.h);
  // Contact at (1/4, 1/4): barycentric weights (1/2, 1/4, 1/4), so w = (1, -1/2, -1/4, -1/4),
  // sum w^2 / m = 1.375; the impulse I = 15 / 1.375 raises vn from -20 to -5.
  const double I = 15.0 / 1.375;
  EXPECT_NEAR(f.v[0].z(), -20.0 + I, 1e-12);
  EXPECT_NEAR(f.v[1].z(), -0.5 * I, 1e-12);
  EXPECT_NEAR(f.v[2].z(), -0.25 * I, 1e-12);
  EXPECT_NEAR(f.v[3].z(), -0.25 * I, 1e-12);
  Vec3 momentum = Vec3::Zero();
  for (const Vec3& v : f.v) momentum += v;
  EXPECT_NEAR((momentum - Vec3(0, 0, -20)).norm(), 0.0, 1e-12);
  const double vn = f.v[0].z() - 0.5 * f.v[1].z() - 0.25 * f.v[2].z() - 0.25 * f.v[3].z();
  EXPECT_NEAR(vn, -5.0, 1e-12);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR((f.x1[i] - f.x0[i] - f.h * f.v[i]).norm(), 0.0, 1e-12) << i;
}

TEST(ContinuousImpulse, CrossingEdgesStopAtHalfTheirGap) {
  // a = (0,0,0)-(1,0,0) pinned; b = (1/2, +-1, z) falling from z = 1 to z = -1 in h = 1: contact
  // at t = 1/2 at both middles (s = r = 1/2, w = (1/2, 1/2, -1/2, -1/2)), n along z oriented from
  // a toward b's start, gap 1; half kept: b ends at z = 1/2, moving at -1/2 m/s.
  std::vector<Vec3> x0 = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, -1, 1), Vec3(0.5, 1, 1)};
  std::vector<Vec3> x1 = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, -1, -1), Vec3(0.5, 1, -1)};
  std::vector<Vec3> v = {Vec3::Zero(), Vec3::Zero(), Vec3(0, 0, -2), Vec3(0, 0, -2)};
  ContinuousContacts c;
  c.edge_edge = {EdgeEdgePair{MeshEdge{0, 1}, MeshEdge{2, 3}}};
  EXPECT_EQ(apply_contact_impulses(c, {}, x0, x1, v, {0.0, 0.0, 1.0, 1.0}, 1.0), 1);
  EXPECT_NEAR(v[2].z(), -0.5, 1e-12);
  EXPECT_NEAR(v[3].z(), -0.5, 1e-12);
  EXPECT_NEAR(x1[2].z(), 0.5, 1e-12);
  EXPECT_NEAR(x1[3].z(), 0.5, 1e-12);
}

TEST(ContinuousImpulse, SeparatingOrSlowContactsAreLeftAlone) {
  // Touching at the start and moving apart: the contact is real (t = 0) but needs no impulse.
  Fall f;
  f.x0[0] = Vec3(0.25, 0.25, 0);
  f.x1[0] = Vec3(0.25, 0.25, 1);
  f.v[0] = Vec3(0, 0, 10);
  const std::vector<double> inv_mass = {1.0, 0.0, 0.0, 0.0};
  EXPECT_EQ(apply_contact_impulses(f.contacts(), kTri, f.x0, f.x1, f.v, inv_mass, f.h), 0);
  EXPECT_EQ(f.v[0], Vec3(0, 0, 10));
  // No contact during the motion (ccd says miss): nothing either.
  Fall g;
  g.x1[0] = Vec3(0.25, 0.25, 0.75);
  EXPECT_EQ(apply_contact_impulses(g.contacts(), kTri, g.x0, g.x1, g.v, inv_mass, g.h), 0);
}

}  // namespace
}  // namespace tecido
