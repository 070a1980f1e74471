// Precision and recall of a reported pair set (comparisons/suites/selfcollision/pair_agreement.*)
// on planted sets with hand-counted answers.
#include "comparisons/suites/selfcollision/pair_agreement.h"

#include <gtest/gtest.h>

namespace tecido::suites::selfcollision {
namespace {

TEST(PairAgreement, DifferenceNamesTheMissedAndTheExtraPairs) {
  // The same planted frame: (1,7) missed, (3,4) and (6,8) invented.
  const PairDifference d = pair_difference({{0, 5}, {2, 9}, {3, 4}, {6, 8}}, {{0, 5}, {1, 7}, {2, 9}});
  EXPECT_EQ(d.missed, (std::vector<std::array<int, 2>>{{1, 7}}));
  EXPECT_EQ(d.extra, (std::vector<std::array<int, 2>>{{3, 4}, {6, 8}}));
  const PairDifference same = pair_difference({{0, 5}}, {{0, 5}});
  EXPECT_TRUE(same.missed.empty() && same.extra.empty());
}

TEST(PairAgreement, PlantedDisagreements) {
  // Truth {(0,5),(1,7),(2,9)}; the engine misses (1,7) and invents (3,4) and (6,8).
  PairAgreement a;
  a.add({{0, 5}, {2, 9}, {3, 4}, {6, 8}}, {{0, 5}, {1, 7}, {2, 9}});
  EXPECT_EQ(a.reported, 4);
  EXPECT_EQ(a.true_positives, 2);
  EXPECT_EQ(a.false_positives, 2);
  EXPECT_EQ(a.missed, 1);
  EXPECT_DOUBLE_EQ(a.precision(), 0.5);
  EXPECT_DOUBLE_EQ(a.recall(), 2.0 / 3.0);
  // A second frame adds up: one more true pair found, nothing invented.
  a.add({{1, 2}}, {{1, 2}});
  EXPECT_DOUBLE_EQ(a.precision(), 3.0 / 5.0);
  EXPECT_DOUBLE_EQ(a.recall(), 3.0 / 4.0);
  PairAgreement empty;
  empty.add({}, {});
  EXPECT_EQ(empty.precision(), 1.0);
  EXPECT_EQ(empty.recall(), 1.0);
}

}  // namespace
}  // namespace tecido::suites::selfcollision
