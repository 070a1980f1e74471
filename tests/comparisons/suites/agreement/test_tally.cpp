// The agreement kit's tally (comparisons/suites/agreement/tally.*) on planted answers counted by
// hand: agreements, false hits, misses, no answers, the time error only where both hit, and each
// disagreement recorded with both answers, indexed from the block's first case and capped.
#include "comparisons/suites/agreement/tally.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace tecido::suites::agreement {
namespace {

Answer hit(double t) { return {true, t}; }
Answer miss() { return {false, 0.0}; }

TEST(AgreementTally, CountsPlantedAnswers) {
  // truth:   hit .5, hit .25, miss, miss, hit 1, miss
  // answers: hit .5+1e-9 (agree), miss (miss), hit (false hit), miss (agree), none, miss (agree)
  const std::vector<Answer> truth = {hit(0.5), hit(0.25), miss(), miss(), hit(1.0), miss()};
  const std::vector<std::optional<Answer>> answers = {hit(0.5 + 1e-9), miss(), hit(0.3), miss(), std::nullopt, miss()};
  std::vector<Disagreement> disagree;
  const Tally t = count_agreement(truth, answers, &disagree, 100, 10);
  EXPECT_EQ(t.cases, 6);
  EXPECT_EQ(t.agree, 3);
  EXPECT_EQ(t.false_hits, 1);
  EXPECT_EQ(t.misses, 1);
  EXPECT_EQ(t.disagreements(), 2);
  EXPECT_EQ(t.no_answer, 1);
  EXPECT_EQ(t.both_hit, 1);
  EXPECT_NEAR(t.max_t_error, 1e-9, 1e-15);
  EXPECT_DOUBLE_EQ(t.rate(), 0.5);
  ASSERT_EQ(disagree.size(), 2u);
  EXPECT_EQ(disagree[0].k, 101);
  EXPECT_FALSE(disagree[0].answer.hit) << "a miss: the engine said miss";
  EXPECT_TRUE(disagree[0].truth.hit);
  EXPECT_EQ(disagree[0].truth.t, 0.25);
  EXPECT_EQ(disagree[1].k, 102);
  EXPECT_TRUE(disagree[1].answer.hit) << "a false hit, at the engine's t";
  EXPECT_EQ(disagree[1].answer.t, 0.3);
  EXPECT_FALSE(disagree[1].truth.hit);
  std::vector<Disagreement> capped;
  count_agreement(truth, answers, &capped, 0, 1);
  ASSERT_EQ(capped.size(), 1u);
  EXPECT_EQ(capped[0].k, 1);
  EXPECT_THROW(count_agreement(truth, {miss()}), std::invalid_argument);
}

TEST(AgreementTally, HitsWithoutTimeCountLikeTritriDid) {
  // truth:   1 0 1 0 1 1
  // answers: 1 1 - 0 0 1   -> agree at 0, 3, 5; no answer at 2; disagree at 1 and 4.
  const std::vector<Answer> truth = {hit(0), miss(), hit(0), miss(), hit(0), hit(0)};
  const std::vector<std::optional<Answer>> answers = {hit(0), hit(0), std::nullopt, miss(), miss(), hit(0)};
  std::vector<Disagreement> disagree;
  const Tally t = count_agreement(truth, answers, &disagree, 100, 10);
  EXPECT_EQ(t.agree, 3);
  EXPECT_EQ(t.cases, 6);
  EXPECT_EQ(t.no_answer, 1);
  EXPECT_EQ(t.false_hits, 1);
  EXPECT_EQ(t.misses, 1);
  EXPECT_DOUBLE_EQ(t.rate(), 0.5);
  ASSERT_EQ(disagree.size(), 2u);
  EXPECT_EQ(disagree[0].k, 101);
  EXPECT_EQ(disagree[1].k, 104);
}

TEST(AgreementTally, NoCaseNoRateAndNoBothHitNoError) {
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

}  // namespace
}  // namespace tecido::suites::agreement
