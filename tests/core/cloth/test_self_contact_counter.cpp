// core/cloth/self_contact_counter.h: frames with self-contact counted by a chosen test. A
// hand-built case where a small triangle stabs through a large one with one edge only: the exact
// test and the rotation test see it, the seed's Möller-Trumbore rule (both ways must hit) does not.
#include "core/cloth/self_contact_counter.h"

#include <gtest/gtest.h>

namespace tecido {
namespace {

/// Two separate triangles: a large one in z = 0 and a small one piercing it through its middle.
struct Stab {
  std::vector<Vec3> x{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0},                 // large, in z = 0
                      {-0.1, 0, -0.5}, {0.1, 0, -0.5}, {0, 0.05, 0.5}};  // small, crossing z = 0 inside it
  std::vector<std::array<int, 3>> tris{{0, 1, 2}, {3, 4, 5}};
};

TEST(SelfContactCounter, NamesRoundTrip) {
  for (ContactTest t : {ContactTest::Core, ContactTest::CoreMt, ContactTest::CoreRotation})
    EXPECT_EQ(parse_contact_test(contact_test_name(t)), t);
  EXPECT_FALSE(parse_contact_test("fcl"));
  EXPECT_FALSE(parse_contact_test(""));
}

TEST(SelfContactCounter, OneSidedPiercingIsMissedOnlyByTheSeedsMollerTrumboreRule) {
  const Stab s;
  SelfContactCounter core(s.tris, s.x, ContactTest::Core), mt(s.tris, s.x, ContactTest::CoreMt),
      rot(s.tris, s.x, ContactTest::CoreRotation);
  EXPECT_EQ(core.count(s.x).size(), 1u);
  EXPECT_EQ(mt.count(s.x).size(), 0u);  // only the small triangle's edges hit the large one
  EXPECT_EQ(rot.count(s.x).size(), 1u);
  EXPECT_EQ(core.counts().contact_frames, 1);
  EXPECT_EQ(mt.counts().contact_frames, 0);
  EXPECT_EQ(mt.counts().frames, 1);
}

TEST(SelfContactCounter, CountsFramesPairsAndTheLargestFrame) {
  Stab s;
  SelfContactCounter c(s.tris, s.x, ContactTest::Core);
  c.count(s.x);
  std::vector<Vec3> apart = s.x;
  for (int i = 3; i < 6; ++i) apart[i].z() += 2.0;  // lifted clear of the large triangle
  EXPECT_TRUE(c.count(apart).empty());
  c.count_pairs(3);
  c.count_pairs(0);
  const SelfContactCount& k = c.counts();
  EXPECT_EQ(k.frames, 4);
  EXPECT_EQ(k.contact_frames, 2);
  EXPECT_EQ(k.pairs, 4);
  EXPECT_EQ(k.max_pairs, 3);
}

}  // namespace
}  // namespace tecido
