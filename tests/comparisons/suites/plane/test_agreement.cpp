// The plane suite's agreement statistics on the agreement kit (comparisons/suites/agreement/; the
// counting itself is tested in tests/comparisons/suites/agreement/) and group_tally.*: case results
// summed per category, groups summed over their categories with the first error as the reason.
#include "comparisons/suites/agreement/block_result.h"
#include "comparisons/suites/plane/group_tally.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::suites::plane {
namespace {

/// A block result (comparisons/suites/agreement/block_result.h) for engines "a" and "b": `a_agree`
/// and `b_agree` of `cases` agree, the rest are false hits; b disagrees on case 7.
io::Json planted_result(long hits, long a_agree, long b_agree, long cases, double a_seconds) {
  auto engine = [&](const char* name, long agree, double seconds, io::Json disagree) {
    return io::Json{{"name", name},
                    {"seconds", seconds},
                    {"tally", {cases, agree, cases - agree, 0, 0, agree > 0 ? 1 : 0, 0}},
                    {"max_t_error", 1e-3},
                    {"disagree", disagree}};
  };
  return {{"hits", hits},
          {"engines",
           {engine("a", a_agree, a_seconds, io::Json::array()),
            engine("b", b_agree, 1.0, io::Json::array({io::Json::array({7, true, 0.5, false, 0.0})}))}}};
}

TEST(PlaneAgreement, CaseResultsSumPerCategoryAndGroupsSumTheirCategories) {
  const auto& cats = categories();  // 0 random, 1 edge, 2 corner
  AgreementTable table = agreement::empty_table(cats.size(), {"a", "b"});
  agreement::add_block(table, {0, 0, 10}, cats[0].random, planted_result(4, 10, 9, 10, 2e-6));
  agreement::add_block(table, {0, 10, 10}, cats[0].random, planted_result(5, 10, 8, 10, 4e-6));
  agreement::add_block(table, {1, 0, 10}, cats[1].random, planted_result(3, 7, 10, 10, 1.0));
  agreement::add_block(table, {2, 0, 10}, cats[2].random, io::Json{{"error", "case 3 threw: broken"}});
  EXPECT_EQ(table.hits[0], 9);
  EXPECT_EQ(table.tally[0][0].cases, 20);
  EXPECT_EQ(table.tally[0][1].agree, 17);
  EXPECT_EQ(table.tally[0][1].false_hits, 3);
  // Timing is summed over the random category only: 6e-6 s over 20 cases.
  EXPECT_NEAR(agreement::ns_per_case(table, 0), 300.0, 1e-9);
  EXPECT_EQ(table.disagree[1].size(), 3u);
  EXPECT_EQ(table.disagree[1][2].family, 1u);
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
  AgreementTable table = agreement::empty_table(categories().size(), {"a", "c"});
  EXPECT_THROW(agreement::add_block(table, {0, 0, 10}, true, planted_result(4, 10, 9, 10, 1.0)), std::runtime_error);
}

}  // namespace
}  // namespace tecido::suites::plane
