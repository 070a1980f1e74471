// The `ccd` suite end to end with --quick: every declared check is produced and passes, the
// report has its tables, and the disagreement file reads back as a queries file whose truths
// are the referee's answers.
#include "comparisons/io/source_dir.h"
#include "comparisons/suites/ccd/ccd_suite.h"

#include "comparisons/io/ccd_queries.h"
#include "comparisons/suites/ccd/families.h"
#include "tests/support/cli_runner.h"
#include "reference/exact_ccd.h"

#include <gtest/gtest.h>

namespace tecido::suites {
namespace {

TEST(CcdSuite, QuickRunPassesEveryDeclaredCheckAndWritesItsDisagreements) {
  const Tolerances tol = Tolerances::load(std::string(TECIDO_SOURCE_DIR) + "/data/tolerances.json");
  SuiteContext ctx;
  ctx.quick = true;
  ctx.seed = 1;
  ctx.threads = 2;
  ctx.tolerances = &tol;
  ctx.out_dir = testing::temp_dir("ccd-suite").string();
  const SuiteResult r = run_ccd_suite(ctx);
  // Per family: 3 checks (+1 constructed; random vertex-face: +8, core's false positives and toi
  // error, FCL's and Bullet's misses, false positives and late toi; random edge-edge: +5, Bullet
  // has no edge-edge test); the sheet: 10.
  std::size_t expected = 10;
  for (const auto& f : ccd::families())
    expected += 3 + (f.constructed ? 1 : 0) + (f.checks_references ? (f.kind == CcdKind::VertexFace ? 8 : 5) : 0);
  EXPECT_EQ(r.checks.size(), expected);
  for (const Check& c : r.checks) EXPECT_TRUE(c.pass) << c.name << " = " << c.value << " " << c.reason;
  EXPECT_NE(r.markdown.find("### vertex-face"), std::string::npos);
  EXPECT_NE(r.markdown.find("### edge-edge"), std::string::npos);
  EXPECT_NE(r.markdown.find("### A sheet through a sheet"), std::string::npos);
  EXPECT_TRUE(r.data.contains("vertex-face/near-miss"));
  EXPECT_TRUE(r.data["vertex-face/random"]["engines"]["fcl"].contains("max_toi_late"));

  // The disagreements: FCL misses coplanar motion, so there are some; each one's truth is the
  // referee's answer on the query as read back.
  const auto entries = io::load_ccd_queries_json(ctx.out_dir + "/ccd/disagreements.json");
  ASSERT_GT(entries.size(), 0u);
  for (const auto& e : entries) {
    ASSERT_TRUE(e.truth.has_value());
    EXPECT_EQ(reference::exact_ccd(e.query).hit, *e.truth) << e.id;
    EXPECT_NE(e.id.rfind("exact:", 0), 0u) << "the referee never disagrees with itself: " << e.id;
  }
}

}  // namespace
}  // namespace tecido::suites
