// The Bullet adapters' shared pieces (reference/bullet_common.h): which springs are Bullet's elastic
// and bending links, read from the cloth spec; and the static box that stands in for a bounded
// plane. Truths: the cloth builder's documented spring order (core/scene/cloth_builder.h) and
// hand-worked boxes.
#include "reference/bullet_common.h"

#include "core/scene/cloth_builder.h"

#include <gtest/gtest.h>

namespace tecido::reference {
namespace {

// A rows x cols cloth with type B springs kb and type A springs ka (0 = none).
Scene grid(int rows, int cols, double kb, double ka) {
  Scene s;
  ClothGridSpec c;
  c.rows = rows;
  c.cols = cols;
  c.spacing = 0.1;
  c.total_mass = 1.0;
  c.stiffness_b = kb;
  c.stiffness_a = ka;
  append_cloth(s, c);
  return s;
}

// Springs per family in the builder's order: type B (horizontal, vertical, diagonal,
// anti-diagonal) then type A, each family row-major.
int type_b_count(int r, int c) { return r * (c - 1) + (r - 1) * c + 2 * (r - 1) * (c - 1); }
int type_a_count(int r, int c) { return r * (c - 2) + (r - 2) * c + 2 * (r - 2) * (c - 2); }

TEST(SpringFamilies, TheClothSpecSaysWhichSpringsBend) {
  const Scene s = grid(4, 5, 60.0, 15.0);
  const int nb = type_b_count(4, 5), na = type_a_count(4, 5);
  ASSERT_EQ(s.forces.springs.size(), static_cast<std::size_t>(nb + na));
  const SpringFamilies f = spring_families(s);
  EXPECT_EQ(f.k_elastic, 60.0);
  EXPECT_EQ(f.k_bending, 15.0);
  EXPECT_TRUE(f.notes.empty());
  for (int k = 0; k < nb + na; ++k) EXPECT_EQ(f.bending[k], k >= nb ? 1 : 0) << "spring " << k;
}

TEST(SpringFamilies, EqualStiffnessesStillFollowTheGrid) {
  // The same value for both types: the spec still names the two-edge springs as bending links.
  const Scene s = grid(3, 3, 20.0, 20.0);
  const SpringFamilies f = spring_families(s);
  const int nb = type_b_count(3, 3);
  for (std::size_t k = 0; k < f.bending.size(); ++k) EXPECT_EQ(f.bending[k], static_cast<int>(k) >= nb ? 1 : 0);
  EXPECT_TRUE(f.notes.empty());
}

TEST(SpringFamilies, AClothWithoutTypeAHasOnlyElasticLinks) {
  const SpringFamilies f = spring_families(grid(3, 4, 50.0, 0.0));
  EXPECT_EQ(f.k_elastic, 50.0);
  EXPECT_EQ(f.k_bending, 50.0);
  for (char b : f.bending) EXPECT_EQ(b, 0);
}

TEST(SpringFamilies, EditedSpringsAreExactWhenTheyMatchTheOtherFamilyAndNotedOtherwise) {
  Scene s = grid(3, 3, 100.0, 40.0);
  s.forces.springs[0].stiffness = 40.0;  // a type B spring with type A's stiffness: exact as bending
  s.forces.springs[1].stiffness = 70.0;  // neither: noted, keeps its family
  const SpringFamilies f = spring_families(s);
  EXPECT_EQ(f.bending[0], 1);
  EXPECT_EQ(f.bending[1], 0);
  ASSERT_EQ(f.notes.size(), 1u);
  EXPECT_EQ(f.notes[0].rfind("per-spring stiffness: 1 of", 0), 0u) << f.notes[0];
}

TEST(SpringFamilies, ExplicitSpringsWithoutAClothUseTheirOwnValues) {
  Scene s;
  for (int i = 0; i < 4; ++i) s.particles.add(Vec3(i, 0, 0), Vec3::Zero(), 1.0, 0.5, false);
  for (double k : {5.0, 7.0, 5.0, 9.0}) s.forces.springs.push_back(Spring{0, 1 + static_cast<int>(s.forces.springs.size() % 3), k, 1.0, 0.0});
  s.forces.springs[2].damping = 0.3;
  const SpringFamilies f = spring_families(s);
  EXPECT_EQ(f.k_elastic, 5.0);  // the first spring's
  EXPECT_EQ(f.k_bending, 7.0);  // the first other value
  EXPECT_EQ(f.bending, (std::vector<char>{0, 1, 0, 1}));  // 9 is nearer 7
  EXPECT_EQ(f.damping, 0.0);
  ASSERT_EQ(f.notes.size(), 2u);
  EXPECT_EQ(f.notes[0].rfind("per-spring stiffness: 1 of 4", 0), 0u) << f.notes[0];
  EXPECT_EQ(f.notes[1].rfind("per-spring damping", 0), 0u) << f.notes[1];
}

TEST(SpringFamilies, SpringsOutsideTheClothAreExplicitData) {
  // A loose particle before the cloth and a spring from it to a cloth node: not a grid spring,
  // elastic because its stiffness is type B's.
  Scene s;
  s.particles.add(Vec3(0, 0, 1), Vec3::Zero(), 1.0, 0.5, false);
  ClothGridSpec c;
  c.rows = c.cols = 3;
  c.spacing = 0.1;
  c.total_mass = 1.0;
  c.stiffness_b = 90.0;
  c.stiffness_a = 30.0;
  append_cloth(s, c);
  s.forces.springs.push_back(Spring{0, 5, 30.0, 1.0, 0.0});
  const SpringFamilies f = spring_families(s);
  EXPECT_EQ(f.bending.back(), 1);  // 30 N/m: the bending family
  EXPECT_TRUE(f.notes.empty());
  // A grid spring of reach 1 starting at the cloth's first particle (1) is type B.
  EXPECT_EQ(s.forces.springs[0].i, 1);
  EXPECT_EQ(f.bending[0], 0);
}

TEST(SpringFamilies, RejectsASpringToANodeThatDoesNotExist) {
  Scene s = grid(3, 3, 1.0, 0.0);
  s.forces.springs[0].j = 99;
  EXPECT_THROW(spring_families(s), std::invalid_argument);
}

TEST(PlaneBox, LiesBehindThePlaneAwayFromTheParticles) {
  Scene s;
  s.particles.add(Vec3(0, 0, 0.5), Vec3::Zero(), 1.0, 0.5, false);
  s.planes.push_back(make_bounded_plane(Vec3(1, 2, 0), Vec3::UnitZ(), Vec3::UnitX(), Vec2(2, 3), 0.5));
  const PlaneBox b = plane_box(s, 0, 0.1, 1e-3);
  EXPECT_TRUE(b.note.empty());
  EXPECT_NEAR((b.centre - Vec3(1, 2, -0.05)).norm(), 0.0, 1e-15);  // front face at z = 0
  EXPECT_EQ(b.half_extents, Vec3(2, 3, 0.05));
  EXPECT_EQ(b.contact_offset, 1e-3);
  EXPECT_LE(b.shape_margin, 0.25 * 0.1);
  // Particles below: the box lies above.
  s.particles.x[0] = Vec3(0, 0, -0.5);
  EXPECT_NEAR(plane_box(s, 0, 0.1, 1e-3).centre.z(), 0.05, 1e-15);
}

TEST(PlaneBox, ParticlesOnBothSidesCentreTheBoxAndSaySo) {
  Scene s;
  s.particles.add(Vec3(0, 0, 0.5), Vec3::Zero(), 1.0, 0.5, false);
  s.particles.add(Vec3(0, 0, -0.5), Vec3::Zero(), 1.0, 0.5, false);
  s.planes.push_back(make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), Vec2(1, 1), 0.5));
  const PlaneBox b = plane_box(s, 0, 0.2, 1e-3);
  EXPECT_EQ(b.centre, Vec3::Zero());
  EXPECT_NEAR(b.contact_offset, 0.1 + 1e-3, 1e-15);
  EXPECT_EQ(b.note.rfind("two-sided plane 0", 0), 0u) << b.note;
}

TEST(NoteNumber, SixSignificantDigits) {
  EXPECT_EQ(note_number(0.1), "0.1");
  EXPECT_EQ(note_number(1e-6), "1e-06");
  EXPECT_EQ(note_number(1.0 / 3.0), "0.333333");
}

}  // namespace
}  // namespace tecido::reference
