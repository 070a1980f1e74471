// The tritri suite's agreement statistics (comparisons/suites/tritri/agreement.*) and its
// disagreement file (disagreements.*) on planted data with hand-counted answers.
#include "comparisons/suites/tritri/agreement.h"
#include "comparisons/suites/tritri/disagreements.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::suites::tritri {
namespace {

TEST(TritriAgreement, CountsAgreementsMissingAnswersAndDisagreements) {
  // truth:   1 0 1 0 1 1
  // answers: 1 1 - 0 0 1   -> agree at 0, 3, 5; no answer at 2; disagree at 1 and 4.
  const std::vector<char> truth = {1, 0, 1, 0, 1, 1};
  const std::vector<std::optional<bool>> answers = {true, true, std::nullopt, false, false, true};
  std::vector<long> disagree;
  const Tally t = count_agreement(truth, answers, &disagree, 100, 10);
  EXPECT_EQ(t.agree, 3);
  EXPECT_EQ(t.pairs, 6);
  EXPECT_EQ(t.no_answer, 1);
  EXPECT_DOUBLE_EQ(t.rate(), 0.5);
  EXPECT_EQ(disagree, (std::vector<long>{101, 104}));
  std::vector<long> capped;
  count_agreement(truth, answers, &capped, 0, 1);
  EXPECT_EQ(capped, std::vector<long>{1});
  EXPECT_TRUE(std::isnan(Tally{}.rate())) << "no pairs: no agreement share";
  EXPECT_THROW(count_agreement({1}, {}, nullptr), std::invalid_argument);
}

/// A case result as tritri_case.h writes it, for two engines.
io::Json planted_case(long intersecting, std::array<long, 3> a, std::array<long, 3> b, std::vector<long> b_disagree,
                      double seconds) {
  return {{"intersecting", intersecting},
          {"engines",
           {{{"name", "core"}, {"seconds", seconds}, {"tally", {a[0], a[1], a[2]}}, {"disagree", io::Json::array()}},
            {{"name", "other"}, {"seconds", 2 * seconds}, {"tally", {b[0], b[1], b[2]}}, {"disagree", b_disagree}}}}};
}

TEST(TritriAgreement, CasesSumPerFamilyAndAnErrorMarksItsFamily) {
  const auto& fams = families();  // 0 random, 1 near-coplanar, 2 coplanar, ...
  AgreementTable table = empty_table(fams.size(), {"core", "other"});
  add_case(table, {0, 0, 10}, fams, planted_case(4, {10, 10, 0}, {8, 10, 1}, {3}, 1e-6));
  add_case(table, {0, 10, 5}, fams, planted_case(1, {5, 5, 0}, {4, 5, 0}, {12}, 5e-7));
  add_case(table, {2, 0, 6}, fams, planted_case(6, {6, 6, 0}, {0, 6, 6}, {}, 1.0));
  add_case(table, {1, 0, 3}, fams, io::Json{{"error", "case 3 threw: boom"}});
  EXPECT_EQ(table.intersecting[0], 5);
  EXPECT_EQ(table.tally[0][0].agree, 15);
  EXPECT_EQ(table.tally[0][1].agree, 12);
  EXPECT_EQ(table.tally[0][1].pairs, 15);
  EXPECT_EQ(table.tally[0][1].no_answer, 1);
  EXPECT_EQ(table.tally[2][1].no_answer, 6);
  EXPECT_EQ(table.error[1], "case 3 threw: boom");
  EXPECT_TRUE(table.error[0].empty());
  // Time counts on the random family only: 1.5e-6 s over 15 pairs is 100 ns per pair.
  EXPECT_NEAR(ns_per_pair(table, 0), 100.0, 1e-9);
  EXPECT_NEAR(ns_per_pair(table, 1), 200.0, 1e-9);
  ASSERT_EQ(table.disagree[1].size(), 2u);
  EXPECT_EQ(table.disagree[1][1].k, 12);
  // Found: other disagrees on 2 random pairs (15 - 12 - 1) and none of the coplanar ones answered.
  EXPECT_EQ(disagreements_found(table), 2);
  EXPECT_THROW(add_case(table, {0, 0, 1}, fams, io::Json{{"intersecting", 0}, {"engines", io::Json::array()}}),
               std::runtime_error);
}

TEST(TritriAgreement, DisagreementFileRegeneratesThePairs) {
  const auto& fams = families();
  AgreementTable table = empty_table(fams.size(), {"core", "other"});
  table.disagree[1] = {{1, 0, 7}, {1, 3, 2}, {1, 3, 9}};
  const auto pairs = disagreement_pairs(5, fams, table, 2);
  ASSERT_EQ(pairs.size(), 2u) << "capped";
  EXPECT_EQ(pairs[0].id, "other:random/7");
  EXPECT_EQ(pairs[1].id, "other:" + fams[3].name + "/2");
  const io::TriPair want = family_pair(5, 3, fams[3], 2);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(pairs[1].b[i], want.b[i]);
}

}  // namespace
}  // namespace tecido::suites::tritri
