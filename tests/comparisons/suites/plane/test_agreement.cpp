// The plane suite's agreement statistics (comparisons/suites/plane/agreement.*) on planted data:
// counts worked by hand, the crossing-fraction error only where both hit, disagreements indexed
// from the block's first case and capped, case results summed per category, groups summed over
// their categories with the first error as the reason.
#include "comparisons/suites/plane/agreement.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::suites::plane {
namespace {

SegmentPlaneHit hit(double t) { return {true, t}; }
SegmentPlaneHit miss() { return {false, 0.0}; }

TEST(PlaneAgreement, CountsPlantedAnswers) {
  // truth:   hit .5, hit .25, miss, miss, hit 1, miss
  // answers: hit .5+1e-9 (agree), miss (miss), hit (false hit), miss (agree), none, miss (agree)
  const std::vector<SegmentPlaneHit> truth = {hit(0.5), hit(0.25), miss(), miss(), hit(1.0), miss()};
  const std::vector<std::optional<SegmentPlaneHit>> answers = {hit(0.5 + 1e-9), miss(), hit(0.3), miss(), std::nullopt, miss()};
  std::vector<long> disagree;
  const Tally t = count_agreement(truth, answers, &disagree, 100, 10);
  EXPECT_EQ(t.cases, 6);
  EXPECT_EQ(t.agree, 3);
  EXPECT_EQ(t.false_hits, 1);
  EXPECT_EQ(t.misses, 1);
  EXPECT_EQ(t.no_answer, 1);
  EXPECT_EQ(t.both_hit, 1);
  EXPECT_NEAR(t.max_t_error, 1e-9, 1e-15);
  EXPECT_DOUBLE_EQ(t.rate(), 0.5);
  EXPECT_EQ(disagree, (std::vector<long>{101, 102}));
  std::vector<long> capped;
  count_agreement(truth, answers, &capped, 0, 1);
  EXPECT_EQ(capped, (std::vector<long>{1}));
  EXPECT_THROW(count_agreement(truth, {miss()}), std::invalid_argument);
}

TEST(PlaneAgreement, NoCaseNoRateAndNoBothHitNoError) {
  EXPECT_TRUE(std::isnan(Tally{}.rate()));
  const Tally t = count_agreement({miss(), hit(0.1)}, {miss(), miss()});
  EXPECT_EQ(t.both_hit, 0);
  Tally sum;
  sum.add(t);
  Tally other = count_agreement({hit(0.5)}, {hit(0.75)});
  EXPECT_DOUBLE_EQ(other.max_t_error, 0.25);
  sum.add(other);
  sum.add(t);
  EXPECT_EQ(sum.cases, 5);
  EXPECT_EQ(sum.agree, 3);  // 1 + 1 + 1
  EXPECT_EQ(sum.misses, 2);
  EXPECT_EQ(sum.both_hit, 1);
  EXPECT_DOUBLE_EQ(sum.max_t_error, 0.25);
}

/// A case result as agreement_case.h writes it, for engines "a" and "b".
io::Json planted_result(long hits, long a_agree, long b_agree, long cases, double a_seconds) {
  auto engine = [&](const char* name, long agree, double seconds, std::vector<long> disagree) {
    return io::Json{{"name", name},
                    {"seconds", seconds},
                    {"tally", {cases, agree, cases - agree, 0, 0, agree > 0 ? 1 : 0, 0}},
                    {"max_t_error", 1e-3},
                    {"disagree", disagree}};
  };
  return {{"hits", hits},
          {"engines", {engine("a", a_agree, a_seconds, {}), engine("b", b_agree, 1.0, {7})}}};
}

TEST(PlaneAgreement, CaseResultsSumPerCategoryAndGroupsSumTheirCategories) {
  const auto& cats = categories();  // 0 random, 1 edge, 2 corner
  AgreementTable table = empty_table(cats.size(), {"a", "b"});
  add_case(table, {0, 0, 10}, cats, planted_result(4, 10, 9, 10, 2e-6));
  add_case(table, {0, 10, 10}, cats, planted_result(5, 10, 8, 10, 4e-6));
  add_case(table, {1, 0, 10}, cats, planted_result(3, 7, 10, 10, 1.0));
  add_case(table, {2, 0, 10}, cats, io::Json{{"error", "case 3 threw: broken"}});
  EXPECT_EQ(table.hits[0], 9);
  EXPECT_EQ(table.tally[0][0].cases, 20);
  EXPECT_EQ(table.tally[0][1].agree, 17);
  EXPECT_EQ(table.tally[0][1].false_hits, 3);
  // Timing is summed over the random category only: 6e-6 s over 20 cases.
  EXPECT_NEAR(ns_per_case(table, 0), 300.0, 1e-9);
  EXPECT_EQ(table.disagree[1].size(), 3u);
  EXPECT_EQ(table.disagree[1][2].category, 1u);
  EXPECT_EQ(table.disagree[1][2].k, 7);
  EXPECT_EQ(table.error[2], "case 3 threw: broken");

  const CategoryGroup random = category_groups()[0], border = category_groups()[1];
  const GroupTally r = group_tally(table, cats, random, 1);
  EXPECT_TRUE(r.error.empty());
  EXPECT_DOUBLE_EQ(r.tally.rate(), 17.0 / 20.0);
  const GroupTally b = group_tally(table, cats, border, 0);
  EXPECT_EQ(b.error, "corner: case 3 threw: broken");
  EXPECT_EQ(b.tally.cases, 10);  // edge only: corner produced nothing
}

TEST(PlaneAgreement, AResultListingOtherEnginesIsRejected) {
  AgreementTable table = empty_table(categories().size(), {"a", "c"});
  EXPECT_THROW(add_case(table, {0, 0, 10}, categories(), planted_result(4, 10, 9, 10, 1.0)), std::runtime_error);
}

}  // namespace
}  // namespace tecido::suites::plane
