// The plane suite's case index (comparisons/suites/plane/case_index.*): the agreement blocks cover
// each case of each category exactly once, category by category, and every sweep index maps to one
// case of one group and back.
#include "comparisons/suites/plane/case_index.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

namespace tecido::suites::plane {
namespace {

Settings small() {
  Settings s = settings(true);
  s.random_cases = 250;
  s.cases_per_category = 70;
  s.block = 100;
  s.contact_time.steps = {0.1, 0.02};
  s.contact_time.levels = {4, 8, 12};
  s.drop.heights = {0.2, 1.0};
  return s;
}

TEST(PlaneCaseIndex, BlocksCoverEveryCaseOnceInCategoryOrder) {
  const Settings s = small();
  const auto& cats = categories();
  const auto ranges = case_ranges(s, cats);
  std::vector<std::set<long>> seen(cats.size());
  std::size_t last_category = 0;
  for (const CaseRange& r : ranges) {
    EXPECT_GE(r.family, last_category);  // category-major
    last_category = r.family;
    EXPECT_GT(r.count, 0);
    EXPECT_LE(r.count, s.block);
    for (long k = r.first; k < r.first + r.count; ++k) EXPECT_TRUE(seen[r.family].insert(k).second) << k;
  }
  for (std::size_t c = 0; c < cats.size(); ++c) {
    const long n = cats[c].random ? 250 : 70;
    ASSERT_EQ(static_cast<long>(seen[c].size()), n) << cats[c].name;
    EXPECT_EQ(*seen[c].begin(), 0);
    EXPECT_EQ(*seen[c].rbegin(), n - 1);
  }
  // random: 100 + 100 + 50; each adversarial category one block of 70.
  EXPECT_EQ(ranges.size(), 3u + 8u);
}

TEST(PlaneCaseIndex, EveryIndexIsOneCaseAndBack) {
  const Settings s = small();
  const Layout l = layout(s, categories(), true);
  EXPECT_EQ(l.size(CaseGroup::Agreement), 11u);
  EXPECT_EQ(l.size(CaseGroup::ContactTime), 2u * 2u * 3u);
  EXPECT_EQ(l.size(CaseGroup::Drop), 2u);
  ASSERT_EQ(case_count(l), 11u + 12u + 2u);
  std::set<std::pair<int, std::size_t>> seen;
  for (std::size_t k = 0; k < case_count(l); ++k) {
    const CaseRef c = case_at(l, k);
    EXPECT_LT(c.i, l.size(c.group));
    EXPECT_TRUE(seen.insert({static_cast<int>(c.group), c.i}).second);
    EXPECT_EQ(case_index(l, c), k);
  }
  EXPECT_EQ(case_at(l, 0).group, CaseGroup::Agreement);
  EXPECT_EQ(case_at(l, 11).group, CaseGroup::ContactTime);
  EXPECT_EQ(case_at(l, 23).group, CaseGroup::Drop);
  EXPECT_THROW(case_at(l, case_count(l)), std::out_of_range);
}

TEST(PlaneCaseIndex, ContactCellsAreIntegratorStepLevelWithTheLevelFastest) {
  const Settings s = small();
  const Layout l = layout(s, categories(), true);
  std::size_t i = 0;
  for (std::size_t a = 0; a < 2; ++a)
    for (std::size_t b = 0; b < 2; ++b)
      for (std::size_t c = 0; c < 3; ++c, ++i) {
        const ContactCell cell = contact_cell(l, i);
        EXPECT_EQ(cell.integrator, a);
        EXPECT_EQ(cell.step, b);
        EXPECT_EQ(cell.level, c);
        EXPECT_EQ(contact_index(l, cell), i);
      }
}

TEST(PlaneCaseIndex, WithoutTheRefereeNoAgreementCase) {
  const Layout l = layout(small(), categories(), false);
  EXPECT_EQ(l.size(CaseGroup::Agreement), 0u);
  EXPECT_EQ(case_count(l), 12u + 2u);
  EXPECT_EQ(case_at(l, 0).group, CaseGroup::ContactTime);
}

}  // namespace
}  // namespace tecido::suites::plane
