// Kinetic boxes (core/geometry/ccd/kinetic_boxes.h): hand-worked motions (the time windows of
// overlap worked out beside each), then random moving boxes on a dyadic grid, where the
// interpolated boxes at dyadic times are exact: "disjoint" must never be said of boxes that
// overlap at some sampled time, and boxes overlapping at t = 0 or t = 1 are never disjoint.
#include "core/geometry/ccd/kinetic_boxes.h"

#include <gtest/gtest.h>

#include <random>

namespace tecido {
namespace {

struct Moving {
  CcdBox b0, b1;
};

// A box with x in [x0, x1] at t = 0 moving to [x0 + dx, x1 + dx], y and z in [0, 1] at rest.
Moving slab_x(double x0, double x1, double dx) {
  return {{x0, 0, 0, x1, 1, 1}, {x0 + dx, 0, 0, x1 + dx, 1, 1}};
}

bool disjoint(const Moving& a, const Moving& b) { return ccd_kinetic_boxes_disjoint(a.b0, a.b1, b.b0, b.b1); }

TEST(CcdKineticBoxes, HandWorkedMotions) {
  const Moving a = slab_x(0, 1, 0);  // at rest
  // [2, 3] moving by -1.5: its lower end 2 - 1.5 t reaches 1 at t = 2/3: they meet.
  EXPECT_FALSE(disjoint(a, slab_x(2, 3, -1.5)));
  // Moving by -0.75: lower end 1.25 at t = 1, never 1: disjoint (their swept boxes overlap).
  EXPECT_TRUE(disjoint(a, slab_x(2, 3, -0.75)));
  // Moving by -1: touches exactly at t = 1 (closed boxes): not disjoint.
  EXPECT_FALSE(disjoint(a, slab_x(2, 3, -1)));
  // Both moving together by +5: [0, 1] and [1.5, 2.5] at every t: disjoint.
  EXPECT_TRUE(disjoint(slab_x(0, 1, 5), slab_x(1.5, 2.5, 5)));
  // Passing through each other: overlap around t = 1/2.
  EXPECT_FALSE(disjoint(slab_x(0, 1, 4), slab_x(4, 5, -4)));
  // Overlap in x only for t in [0, 0.4], in y only for t in [0.6, 1]: never both.
  //   A = [0,1]^3 at rest; B x in [0.5 + 1.25 t, 1.5 + 1.25 t]: overlaps A in x while
  //   0.5 + 1.25 t <= 1, t <= 0.4; B y in [1.75 - 1.25 t, 2.75 - 1.25 t]: overlaps in y while
  //   1.75 - 1.25 t <= 1, t >= 0.6; z overlaps always.
  const Moving b{{0.5, 1.75, 0, 1.5, 2.75, 1}, {1.75, 0.5, 0, 2.75, 1.5, 1}};
  EXPECT_TRUE(disjoint(a, b));
  // Shift B's y window earlier (y lower end 1.25 - 1.25 t <= 1 for t >= 0.2): overlap on
  // [0.2, 0.4].
  const Moving c{{0.5, 1.25, 0, 1.5, 2.25, 1}, {1.75, 0.0, 0, 2.75, 1.0, 1}};
  EXPECT_FALSE(disjoint(a, c));
  // Symmetric in the two boxes.
  EXPECT_TRUE(disjoint(b, a));
  EXPECT_FALSE(disjoint(c, a));
}

TEST(CcdKineticBoxes, NeverDisjointWhenTheyMeetAtASampledTime) {
  // Coordinates on a grid of 1/16 in [-4, 4] and times k / 64: (1 - t) lo0 + t lo1 is exact,
  // so the sampled overlap test below is exact.
  std::mt19937_64 rng(1234);
  std::uniform_int_distribution<int> g(-64, 64);
  auto coord = [&] { return g(rng) / 16.0; };
  int said_disjoint = 0, met = 0;
  for (int k = 0; k < 20000; ++k) {
    Moving m[2];
    for (Moving& b : m) {
      for (CcdBox* box : {&b.b0, &b.b1}) {
        for (int c = 0; c < 3; ++c) {
          const double p = coord(), q = coord();
          (*box)[c] = std::min(p, q);
          (*box)[c + 3] = std::max(p, q);
        }
      }
    }
    bool meets = false;
    for (int s = 0; s <= 64 && !meets; ++s) {
      const double t = s / 64.0;
      bool all = true;
      for (int c = 0; c < 3; ++c) {
        const double alo = (1 - t) * m[0].b0[c] + t * m[0].b1[c], ahi = (1 - t) * m[0].b0[c + 3] + t * m[0].b1[c + 3];
        const double blo = (1 - t) * m[1].b0[c] + t * m[1].b1[c], bhi = (1 - t) * m[1].b0[c + 3] + t * m[1].b1[c + 3];
        all = all && alo <= bhi && blo <= ahi;
      }
      meets = all;
    }
    const bool d = disjoint(m[0], m[1]);
    if (meets) {
      EXPECT_FALSE(d) << k;
    }
    said_disjoint += d;
    met += meets;
  }
  EXPECT_GT(said_disjoint, 1000);  // the test must decide something
  EXPECT_GT(met, 1000);
}

}  // namespace
}  // namespace tecido
