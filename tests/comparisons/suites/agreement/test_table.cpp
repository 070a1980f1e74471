// The agreement kit's table (comparisons/suites/agreement/table.*, block_result.*, case_blocks.*,
// disagreements.h) on planted block results: blocks cover each case once, results sum per family,
// time counts on the random family only, an error marks its family, a result listing other
// engines is rejected, and the kept disagreements regenerate their cases with the engine's name.
#include "comparisons/suites/agreement/block_result.h"
#include "comparisons/suites/agreement/disagreements.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <utility>

namespace tecido::suites::agreement {
namespace {

TEST(AgreementBlocks, CoverEachCaseOnceFamilyByFamily) {
  const std::vector<CaseRange> blocks = case_ranges({25, 7, 0, 10}, 10);
  // 10 + 10 + 5; one block of 7; none; one of 10.
  ASSERT_EQ(blocks.size(), 5u);
  EXPECT_EQ(blocks[2].family, 0u);
  EXPECT_EQ(blocks[2].first, 20);
  EXPECT_EQ(blocks[2].count, 5);
  EXPECT_EQ(blocks[3].family, 1u);
  EXPECT_EQ(blocks[4].family, 3u);
  std::set<std::pair<std::size_t, long>> seen;
  for (const CaseRange& b : blocks)
    for (long k = b.first; k < b.first + b.count; ++k) EXPECT_TRUE(seen.insert({b.family, k}).second);
  EXPECT_EQ(seen.size(), 42u);
  EXPECT_EQ(case_ranges({3}, 0).size(), 3u) << "a block below 1 counts as 1";
}

/// A block for engines "core" (agrees on all) and "other" (answers `other`).
io::Json planted_block(const std::vector<Answer>& truth, const std::vector<std::optional<Answer>>& other, double seconds) {
  EngineRun core{"core", seconds, {}, 3};
  for (const Answer& a : truth) core.answers.push_back(a);
  EngineRun b{"other", 2 * seconds, other, 0};
  return block_result(truth, {core, b}, 10, 100);
}

TEST(AgreementTable, BlocksSumPerFamilyAndAnErrorMarksItsFamily) {
  const std::vector<Answer> truth = {{true, 0.5}, {false, 0}, {true, 0.25}, {false, 0}, {false, 0}};
  const std::vector<std::optional<Answer>> other = {Answer{true, 0.5}, Answer{true, 0.125}, std::nullopt,
                                                    Answer{false, 0}, Answer{false, 0}};
  AgreementTable table = empty_table(3, {"core", "other"});
  add_block(table, {0, 10, 5}, true, planted_block(truth, other, 1e-6));
  add_block(table, {0, 15, 5}, true, planted_block(truth, other, 5e-7));
  add_block(table, {2, 10, 5}, false, planted_block(truth, other, 1.0));
  add_block(table, {1, 0, 3}, false, io::Json{{"error", "case 3 threw: boom"}});
  EXPECT_EQ(table.hits[0], 4);
  EXPECT_EQ(table.tally[0][0].agree, 10);
  EXPECT_EQ(table.tally[0][0].exact_path, 6);
  EXPECT_EQ(table.tally[0][1].agree, 6);
  EXPECT_EQ(table.tally[0][1].cases, 10);
  EXPECT_EQ(table.tally[0][1].no_answer, 2);
  EXPECT_EQ(table.tally[0][1].false_hits, 2);
  EXPECT_EQ(table.tally[2][1].both_hit, 1);
  EXPECT_EQ(table.error[1], "case 3 threw: boom");
  EXPECT_TRUE(table.error[0].empty());
  // Time counts on the random family only: 1.5e-6 s over 10 cases is 150 ns per case.
  EXPECT_NEAR(ns_per_case(table, 0), 150.0, 1e-9);
  EXPECT_NEAR(ns_per_case(table, 1), 300.0, 1e-9);
  ASSERT_EQ(table.disagree[1].size(), 3u);
  const Disagreement& d = table.disagree[1][2];
  EXPECT_EQ(d.engine, 1u);
  EXPECT_EQ(d.family, 2u);
  EXPECT_EQ(d.k, 11) << "offset by the block's first case";
  EXPECT_TRUE(d.answer.hit);
  EXPECT_EQ(d.answer.t, 0.125);
  EXPECT_FALSE(d.truth.hit);
  EXPECT_EQ(disagreements_found(table), 3);
  EXPECT_THROW(add_block(table, {0, 0, 1}, true, io::Json{{"hits", 0}, {"engines", io::Json::array()}}),
               std::runtime_error);
  AgreementTable renamed = empty_table(3, {"core", "another"});
  EXPECT_THROW(add_block(renamed, {0, 10, 5}, true, planted_block(truth, other, 1.0)), std::runtime_error);
}

struct Labelled {
  std::string id;
  long k = 0;
};

TEST(AgreementDisagreements, KeptInEngineThenCaseOrderCappedAndRegenerated) {
  AgreementTable table = empty_table(4, {"core", "other"});
  table.disagree[0] = {{0, 2, 4, {}, {}}};
  table.disagree[1] = {{1, 0, 7, {}, {}}, {1, 3, 2, {}, {}}, {1, 3, 9, {}, {}}};
  const std::vector<Disagreement> kept = kept_disagreements(table, 3);
  ASSERT_EQ(kept.size(), 3u) << "capped";
  const auto cases = disagreement_cases<Labelled>(table, kept, [](std::size_t f, long k) {
    return Labelled{"f" + std::to_string(f) + "/" + std::to_string(k), k};
  });
  ASSERT_EQ(cases.size(), 3u);
  EXPECT_EQ(cases[0].id, "core:f2/4");
  EXPECT_EQ(cases[1].id, "other:f0/7");
  EXPECT_EQ(cases[2].id, "other:f3/2");
  EXPECT_EQ(cases[2].k, 2);
}

}  // namespace
}  // namespace tecido::suites::agreement
