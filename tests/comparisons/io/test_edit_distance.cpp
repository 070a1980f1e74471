// The distance behind "did you mean ...?" (comparisons/io/edit_distance.h): worked cases of the
// optimal string alignment distance, and which candidates are close enough to suggest.
#include "comparisons/io/edit_distance.h"

#include <gtest/gtest.h>

namespace tecido {
namespace {

using io::edit_distance;
using io::nearest_words;

TEST(EditDistance, WorkedCases) {
  EXPECT_EQ(edit_distance("", ""), 0u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("abc", ""), 3u);
  EXPECT_EQ(edit_distance("dt", "dt"), 0u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);  // k->s, e->i, +g
  EXPECT_EQ(edit_distance("gravty", "gravity"), 1u);  // one insertion
  EXPECT_EQ(edit_distance("stpes", "steps"), 1u);     // one swap of neighbours
  EXPECT_EQ(edit_distance("ca", "abc"), 3u);          // OSA: the swapped pair is not edited again
  EXPECT_EQ(edit_distance("stiffness", "stiffness_a"), 2u);
  EXPECT_EQ(edit_distance("abc", "xyz"), edit_distance("xyz", "abc"));
}

TEST(EditDistance, NearestWordsKeepsTiesAndOnlyCloseOnes) {
  const std::vector<std::string> cloth = {"rows", "cols", "spacing", "origin", "axis_u", "axis_v", "total_mass",
                                          "stiffness_b", "stiffness_a", "damping", "elasticity", "pins"};
  EXPECT_EQ(nearest_words("stiffness", cloth), (std::vector<std::string>{"stiffness_b", "stiffness_a"}));
  EXPECT_EQ(nearest_words("elastcity", cloth), (std::vector<std::string>{"elasticity"}));
  EXPECT_EQ(nearest_words("row", cloth), (std::vector<std::string>{"rows"}));
  // 9 letters allow 3 edits; "temperature" is nothing like a cloth key: no guess.
  EXPECT_TRUE(nearest_words("temperature", cloth).empty());
  // A short key allows one edit only: "xy" is 2 from "dt" and gets no guess.
  EXPECT_TRUE(nearest_words("xy", {"dt"}).empty());
  EXPECT_EQ(nearest_words("dx", {"dt"}), (std::vector<std::string>{"dt"}));
  // A key far longer than every candidate is not compared at all (and gets no guess).
  EXPECT_TRUE(nearest_words(std::string(100000, 'k'), cloth).empty());
}

}  // namespace
}  // namespace tecido
