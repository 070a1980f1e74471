// The tritri suite on the agreement kit (comparisons/suites/agreement/): one case (tritri_case.*)
// tallies every engine against the referee on hand-checkable engines, and the disagreement file's
// pairs are regenerated from (seed, family, k).
#include "comparisons/suites/agreement/block_result.h"
#include "comparisons/suites/agreement/disagreements.h"
#include "comparisons/suites/tritri/tritri_case.h"
#include "core/geometry/tri_tri_intersect.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::suites::tritri {
namespace {

std::optional<bool> always_true(const Triangle&, const Triangle&) { return true; }
std::optional<bool> never(const Triangle&, const Triangle&) { return std::nullopt; }
std::optional<bool> core_test(const Triangle& a, const Triangle& b) { return tri_tri_intersect(a, b); }

TEST(TritriAgreement, ACaseTalliesEveryEngineAgainstTheReferee) {
  const auto& fams = families();
  const TriTriEngine referee{"exact", &core_test};
  const std::vector<TriTriEngine> engines = {{"core", &core_test}, {"liar", &always_true}, {"mute", &never}};
  const io::Json r = run_tritri_case(5, fams, {0, 100, 200}, referee, engines, 1000);
  long intersecting = 0;
  for (long k = 100; k < 300; ++k) {
    const io::TriPair p = family_pair(5, 0, fams[0], k);
    intersecting += tri_tri_intersect(p.a, p.b);
  }
  agreement::AgreementTable table = agreement::empty_table(fams.size(), {"core", "liar", "mute"});
  agreement::add_block(table, {0, 100, 200}, true, r);
  EXPECT_EQ(table.hits[0], intersecting);
  EXPECT_EQ(table.tally[0][0].agree, 200);
  EXPECT_EQ(table.tally[0][1].agree, intersecting) << "the liar agrees exactly on the intersecting pairs";
  EXPECT_EQ(table.tally[0][1].false_hits, 200 - intersecting);
  EXPECT_EQ(table.tally[0][1].misses, 0);
  EXPECT_EQ(table.tally[0][2].no_answer, 200) << "no answer: neither agrees nor disagrees";
  EXPECT_EQ(agreement::disagreements_found(table), 200 - intersecting);
  ASSERT_EQ(table.disagree[1].size(), static_cast<std::size_t>(200 - intersecting));
  for (const agreement::Disagreement& d : table.disagree[1]) {
    EXPECT_GE(d.k, 100);
    EXPECT_TRUE(d.answer.hit);
    EXPECT_FALSE(d.truth.hit);
  }
  EXPECT_TRUE(std::isfinite(agreement::ns_per_case(table, 1)));
}

TEST(TritriAgreement, DisagreementFileRegeneratesThePairs) {
  const auto& fams = families();
  agreement::AgreementTable table = agreement::empty_table(fams.size(), {"core", "other"});
  table.disagree[1] = {{1, 0, 7, {}, {}}, {1, 3, 2, {}, {}}, {1, 3, 9, {}, {}}};
  const auto pairs = agreement::disagreement_cases<io::TriPair>(
      table, agreement::kept_disagreements(table, 2),
      [&fams](std::size_t f, long k) { return family_pair(5, f, fams.at(f), k); });
  ASSERT_EQ(pairs.size(), 2u) << "capped";
  EXPECT_EQ(pairs[0].id, "other:random/7");
  EXPECT_EQ(pairs[1].id, "other:" + fams[3].name + "/2");
  const io::TriPair want = family_pair(5, 3, fams[3], 2);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(pairs[1].b[i], want.b[i]);
}

}  // namespace
}  // namespace tecido::suites::tritri
