// comparisons/suites/self_contact/grid.h: the 72 cells in the seed's table order, index <-> key.
#include "comparisons/suites/self_contact/grid.h"

#include <gtest/gtest.h>

namespace tecido::suites::self_contact {
namespace {

TEST(CellGrid, SeventyTwoCellsInTheDocumentedOrder) {
  ASSERT_EQ(CellGrid::kCells, 72);
  const double dts[3] = {0.02, 0.01, 0.005}, winds[3] = {0.09, 0.1, 0.11};
  for (int i = 0; i < 72; ++i) {
    const Cell c = CellGrid::cell(i);
    EXPECT_EQ(c.index, i);
    EXPECT_EQ(c.mode, i % 4);
    EXPECT_EQ(c.elasticity, (i / 4) % 2 == 0 ? 0.9 : 0.5);
    EXPECT_EQ(c.dt, dts[(i / 8) % 3]);
    EXPECT_EQ(c.wind, winds[i / 24]);
  }
  EXPECT_EQ(CellGrid::cell(0).steps_per_second(), 50);
  EXPECT_EQ(CellGrid::cell(71).steps_per_second(), 200);
}

TEST(CellGrid, KeyAndIndexAreInverse) {
  int expected = 0;
  for (int w = 0; w < 3; ++w)
    for (int s = 0; s < 3; ++s)
      for (int e = 0; e < 2; ++e)
        for (int m = 0; m < 4; ++m) {
          const CellKey k{w, s, e, m};
          EXPECT_EQ(CellGrid::index(k), expected);
          EXPECT_TRUE(CellGrid::key(expected) == k);
          ++expected;
        }
  EXPECT_EQ(CellGrid::with_mode(CellGrid::index({2, 1, 1, 0}), 3), CellGrid::index({2, 1, 1, 3}));
  EXPECT_EQ(mode_label(0), "none");
  EXPECT_EQ(mode_label(2), "mode 2");
  EXPECT_STREQ(mode_response_name(3), "edge3");
}

}  // namespace
}  // namespace tecido::suites::self_contact
