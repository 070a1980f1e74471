// The tritri suite as a whole (comparisons/suites/tritri/tritri_suite.*): a family whose cases
// throw fails its own checks with the reason and nothing else; an engine that always answers
// "intersecting" is scored by the share of pairs that really intersect; and with every number of
// its tolerance section changed the suite reports the same checks after the same work, failing
// (exit 1) when a band excludes the values.
#include "comparisons/suites/tritri/tritri_suite.h"

#include "comparisons/suites/tritri/case_index.h"
#include "core/geometry/tri_tri_intersect.h"
#include "tests/support/cli_runner.h"
#include "tests/support/tolerance_file.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <stdexcept>

namespace tecido::suites {
namespace {

using testing::run_cli;

io::TriPair broken_pair(Rng&, long k) {
  if (k >= 0) throw std::runtime_error("broken generator");
  return {};
}

std::optional<bool> always_true(const Triangle&, const Triangle&) { return true; }
std::optional<bool> core_test(const Triangle& a, const Triangle& b) { return tri_tri_intersect(a, b); }

TEST(TritriSuite, AThrowingFamilyFailsItsChecksWithTheReason) {
  const Tolerances tol(io::Json::parse(R"({"tritri":{"core_min_agreement":1,"liar_min_agreement":0}})"), "tol.json");
  const auto dir = testing::temp_dir("tritri-broken");
  SuiteContext ctx;
  ctx.seed = 5;
  ctx.tolerances = &tol;
  ctx.out_dir = dir.string();
  std::vector<tritri::Family> fams = {tritri::families().front(), {"broken", "throws", &broken_pair}};
  // The referee is core's own exact test here: the test is about the suite's bookkeeping.
  const std::vector<TriTriEngine> engines = {{"core", &core_test}, {"liar", &always_true}, {"exact", &core_test}};
  tritri::Settings set;
  set.random_pairs = 5000;
  set.pairs_per_family = 300;
  set.block = 1000;
  const Sweep s = tritri_sweep_for(ctx, set, fams, engines);
  EXPECT_EQ(s.cases, 6u);
  std::vector<std::size_t> all(s.cases);
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
  const SuiteResult r = s.assemble(run_sweep_cases(s, all, 2, "t", false));

  ASSERT_EQ(r.checks.size(), 3u);
  EXPECT_EQ(r.checks[0].name, "tritri/core/agreement/random");
  EXPECT_TRUE(r.checks[0].pass);
  EXPECT_EQ(r.checks[0].value, 1.0);
  EXPECT_EQ(r.checks[1].name, "tritri/core/agreement/broken");
  EXPECT_FALSE(r.checks[1].pass);
  EXPECT_NE(r.checks[1].reason.find("broken generator"), std::string::npos) << r.checks[1].reason;
  EXPECT_EQ(r.checks[2].name, "tritri/liar/agreement/random");
  // The liar agrees exactly on the intersecting pairs: count them independently.
  long intersecting = 0;
  for (long k = 0; k < set.random_pairs; ++k) {
    const io::TriPair p = tritri::family_pair(substream(ctx.seed, 2), 0, fams[0], k);
    intersecting += tri_tri_intersect(p.a, p.b);
  }
  EXPECT_DOUBLE_EQ(r.checks[2].value, static_cast<double>(intersecting) / static_cast<double>(set.random_pairs));
  EXPECT_TRUE(r.checks[2].pass);
  EXPECT_NE(r.markdown.find("Family `broken` failed"), std::string::npos);
  const auto file = nlohmann::json::parse(testing::slurp(dir / "tritri" / "disagreements.json"));
  EXPECT_EQ(file["pairs"].size(), static_cast<std::size_t>(set.random_pairs - intersecting));
  for (const auto& p : file["pairs"]) {
    EXPECT_EQ(p["id"].get<std::string>().rfind("liar:random/", 0), 0u);
    // Each names its engine and both answers: the liar's hit where the referee says none.
    EXPECT_EQ(p["engine"], "liar");
    EXPECT_EQ(p["answer"], nlohmann::json::parse(R"({"hit":true})"));
    EXPECT_EQ(p["referee"], nlohmann::json::parse(R"({"hit":false})"));
    EXPECT_EQ(p["truth"], false);
  }
  // Misses and false hits apart: every disagreement of the liar is a false hit.
  const long false_hits = set.random_pairs - intersecting;
  EXPECT_NE(r.markdown.find(fmt::format("{}/{} ({} false hits)", intersecting, set.random_pairs, false_hits)),
            std::string::npos) << r.markdown;
  EXPECT_NE(r.markdown.find("false hits on random"), std::string::npos);
  ASSERT_EQ(r.stderr_lines.size(), 1u);
  EXPECT_EQ(r.stderr_lines[0].rfind(fmt::format("tritri: liar: 0 misses (false negatives), {} false hits (false "
                                                "positives); first: liar:random/",
                                                false_hits),
                                    0),
            0u) << r.stderr_lines[0];
  EXPECT_NE(r.stderr_lines[0].find("--pairs " + std::filesystem::absolute(dir / "tritri" / "disagreements.json").lexically_normal().string() +
                                   " --engines liar --of-engine liar --json"),
            std::string::npos) << r.stderr_lines[0];
  std::filesystem::remove_all(dir);
}

TEST(TritriSuite, EveryToleranceChangedSameChecksSameWork) {
  const auto dir = testing::temp_dir("tritri-tolerances");
  const auto q = [](const std::filesystem::path& p) { return "'" + p.string() + "'"; };
  const auto base = run_cli("suite tritri --quick --out " + q(dir / "base"));
  ASSERT_EQ(base.code, 0) << base.err;
  const auto want = nlohmann::json::parse(testing::slurp(dir / "base" / "report.json"));
  ASSERT_FALSE(testing::check_names(want).empty());
  // Lowered: every band still holds the values. Raised: every lower bound above 1, so every check fails.
  ASSERT_GT(testing::write_changed_tolerances(dir / "low.json", {"tritri"}, [](double x) { return 0.5 * x - 0.25; }), 0);
  testing::write_changed_tolerances(dir / "high.json", {"tritri"}, [](double x) { return x + 0.5; });
  for (const char* name : {"low", "high"}) {
    const auto r = run_cli("suite tritri --quick --tolerances " + q(dir / (std::string(name) + ".json")) + " --out " +
                           q(dir / name));
    const auto got = nlohmann::json::parse(testing::slurp(dir / name / "report.json"));
    EXPECT_EQ(testing::check_names(got), testing::check_names(want)) << name;
    EXPECT_EQ(testing::data_without_timings(got), testing::data_without_timings(want)) << name << ": other work";
    const bool high = std::string(name) == "high";
    EXPECT_EQ(r.code, high ? 1 : 0) << name << ": " << r.err;
    for (const auto& c : got["suites"][0]["checks"]) EXPECT_EQ(c["pass"].get<bool>(), !high) << c.dump();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido::suites
