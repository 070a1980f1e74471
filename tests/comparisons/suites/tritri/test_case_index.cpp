// The tritri suite's cases (comparisons/suites/tritri/case_index.*): family by family, in blocks,
// each pair of each family in exactly one case.
#include "comparisons/suites/tritri/case_index.h"

#include <gtest/gtest.h>

#include <set>
#include <utility>

namespace tecido::suites::tritri {
namespace {

TEST(TritriCaseIndex, BlocksCoverEachPairOnceFamilyByFamily) {
  Settings s;
  s.random_pairs = 25;
  s.pairs_per_family = 7;
  s.block = 10;
  const auto& fams = families();
  const std::vector<CaseRange> cases = case_ranges(s, fams);
  // random: 10 + 10 + 5; every other family: one block of 7.
  ASSERT_EQ(cases.size(), 3 + (fams.size() - 1));
  EXPECT_EQ(cases[2].family, 0u);
  EXPECT_EQ(cases[2].first, 20);
  EXPECT_EQ(cases[2].count, 5);
  std::set<std::pair<std::size_t, long>> seen;
  std::size_t last_family = 0;
  for (const CaseRange& c : cases) {
    EXPECT_GE(c.family, last_family) << "family-major order";
    last_family = c.family;
    EXPECT_GT(c.count, 0);
    EXPECT_LE(c.count, s.block);
    for (long k = c.first; k < c.first + c.count; ++k) EXPECT_TRUE(seen.insert({c.family, k}).second) << c.family << "/" << k;
  }
  std::size_t want = 0;
  for (const Family& f : fams) want += static_cast<std::size_t>(family_pairs(s, f));
  EXPECT_EQ(seen.size(), want);
  EXPECT_EQ(want, 25u + 7u * (fams.size() - 1));
}

TEST(TritriCaseIndex, TheSuiteSettingsGiveWholeBlocks) {
  for (bool quick : {false, true}) {
    const Settings s = settings(quick);
    const std::vector<CaseRange> cases = case_ranges(s, families());
    const std::size_t random_cases = static_cast<std::size_t>((s.random_pairs + s.block - 1) / s.block);
    const std::size_t per_family = static_cast<std::size_t>((s.pairs_per_family + s.block - 1) / s.block);
    EXPECT_EQ(cases.size(), random_cases + per_family * (families().size() - 1)) << quick;
  }
  EXPECT_LT(settings(true).random_pairs, settings(false).random_pairs);
}

TEST(TritriCaseIndex, NoPairsNoCases) {
  Settings s;
  s.random_pairs = 0;
  s.pairs_per_family = 0;
  EXPECT_TRUE(case_ranges(s, families()).empty());
}

}  // namespace
}  // namespace tecido::suites::tritri
