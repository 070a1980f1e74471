// The plane suite as a whole (comparisons/suites/plane/plane_suite.*) cannot lie: a category whose
// generator throws fails its group's checks with the reason and nothing else; an engine that always
// answers "hit" is scored by the share of cases that really hit; a t_error check with no case where
// both hit fails instead of passing; a contact-time cell or a drop that throws fails the check it
// feeds. Through the CLI: with every /plane/ number changed the suite reports the same checks after
// the same work, failing (exit 1) where a band excludes the value; shards merge into the same report.
#include "comparisons/io/source_dir.h"
#include "comparisons/suites/plane/plane_suite.h"

#include "tests/support/cli_runner.h"
#include "tests/support/tolerance_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <map>
#include <stdexcept>

namespace tecido::suites::plane {
namespace {

using testing::run_cli;

/// Small settings: the whole sweep runs in well under a second, also under the sanitizers.
Settings small_suite() {
  Settings s = settings(true);
  s.random_cases = 300;
  s.cases_per_category = 60;
  s.block = 100;
  s.contact_time.drops = 3;
  s.contact_time.steps = {0.1, 0.02};
  s.contact_time.levels = {4, 8};
  s.drop.heights = {0.2, 1.0};
  return s;
}

io::PlaneCase broken_case(Rng&, long k) {
  if (k >= 0) throw std::runtime_error("broken generator");
  return {};
}

std::optional<SegmentPlaneHit> core_test(const BoundedPlane& p, const Vec3& a, const Vec3& b) { return segment_plane(p, a, b); }
std::optional<SegmentPlaneHit> always_hit(const BoundedPlane&, const Vec3&, const Vec3&) { return SegmentPlaneHit{true, 0.5}; }
std::optional<SegmentPlaneHit> never_hit(const BoundedPlane&, const Vec3&, const Vec3&) { return SegmentPlaneHit{}; }

/// The referee is core's own exact test here: these tests are about the suite's bookkeeping.
std::vector<SegmentPlaneEngine> stand_in_engines() {
  return {{"core", &core_test}, {"liar", &always_hit}, {"never", &never_hit}, {"exact", &core_test}};
}

Tolerances planted_tolerances() {
  io::Json doc = Tolerances::load(std::string(TECIDO_SOURCE_DIR) + "/data/tolerances.json").doc();
  for (const char* e : {"liar", "never"}) {
    for (const char* g : {"random", "border", "exact-geometry", "grazing", "far"})
      doc["plane"][std::string(e) + "_agreement_" + g] = 0.0;
    doc["plane"][std::string(e) + "_t_error_near"] = 1.0;
    doc["plane"][std::string(e) + "_t_error_far"] = 1.0;
  }
  return Tolerances(doc, "planted.json");
}

struct Fixture {
  Tolerances tol = planted_tolerances();
  std::filesystem::path dir;
  SuiteContext ctx;
  Plan plan;
  std::vector<io::Json> results;
  explicit Fixture(std::vector<Category> cats = categories()) : dir(testing::temp_dir("plane-suite")) {
    ctx.seed = 5;
    ctx.tolerances = &tol;
    ctx.out_dir = dir.string();
    plan = make_plan(ctx, small_suite(), std::move(cats), stand_in_engines());
    for (std::size_t k = 0; k < case_count(plan.layout); ++k) {
      try {
        results.push_back(run_case(plan, k));
      } catch (const std::exception& e) {  // what the sweep does with a case that throws
        results.push_back(io::Json{{"error", std::string("case ") + std::to_string(k) + " threw: " + e.what()}});
      }
    }
  }
  ~Fixture() { std::filesystem::remove_all(dir); }
  SuiteResult assembled(const std::vector<io::Json>& r) const { return assemble(plan, dir.string(), r); }
  std::map<std::string, Check> checks(const std::vector<io::Json>& r) const {
    std::map<std::string, Check> out;
    for (const Check& c : assembled(r).checks) out[c.name] = c;
    return out;
  }
};

TEST(PlaneSuite, EveryDeclaredCheckGetsAValue) {
  const Fixture f;
  const SuiteResult r = f.assembled(f.results);
  ASSERT_EQ(r.checks.size(), f.plan.checks.size());
  for (const Check& c : r.checks) {
    // `never` never hits, so no case where it and the referee both hit: no t error to check.
    if (c.name.rfind("plane/never/t_error/", 0) == 0) {
      EXPECT_FALSE(c.pass) << c.name;
      EXPECT_NE(c.reason.find("where both never and the referee hit"), std::string::npos) << c.reason;
      continue;
    }
    EXPECT_TRUE(c.reason.empty()) << c.name << ": " << c.reason;
    EXPECT_TRUE(c.pass) << c.name << " = " << c.value;
  }
  EXPECT_TRUE(std::filesystem::exists(f.dir / "plane" / "disagreements.json"));
  EXPECT_TRUE(std::filesystem::exists(f.dir / "plane" / "contact_time.dat"));
  EXPECT_TRUE(r.data.contains("agreement") && r.data.contains("contact_time") && r.data.contains("drop"));
  EXPECT_NE(r.markdown.find("settings.h"), std::string::npos);
}

TEST(PlaneSuite, TheLiarScoresTheShareOfCasesThatHit) {
  const Fixture f;
  const auto c = f.checks(f.results);
  // Count the random cases that hit independently of the suite, with core's exact test.
  const Category& random = f.plan.categories[0];
  long hits = 0;
  for (long k = 0; k < f.plan.settings.random_cases; ++k) {
    const io::PlaneCase pc = category_case(substream(f.ctx.seed, 1), 0, random, k);
    hits += segment_plane(pc.plane, pc.from, pc.to).hit;
  }
  const double n = static_cast<double>(f.plan.settings.random_cases);
  EXPECT_DOUBLE_EQ(c.at("plane/liar/agreement/random").value, hits / n);
  EXPECT_DOUBLE_EQ(c.at("plane/never/agreement/random").value, 1.0 - hits / n);
  const auto file = nlohmann::json::parse(testing::slurp(f.dir / "plane" / "disagreements.json"));
  long liar_random = 0;
  for (const auto& x : file["cases"]) {
    const std::string id = x["id"];
    liar_random += id.rfind("liar:random/", 0) == 0;
    // Each entry names its engine, its answer and the referee's, and the referee's hit as truth.
    EXPECT_EQ(id.rfind(x["engine"].get<std::string>() + ":", 0), 0u) << id;
    EXPECT_NE(x["answer"]["hit"], x["referee"]["hit"]) << id;
    EXPECT_EQ(x["truth"], x["referee"]["hit"]) << id;
    EXPECT_EQ(x["referee"]["t"].is_null(), !x["referee"]["hit"].get<bool>()) << id;
  }
  EXPECT_EQ(liar_random, f.plan.settings.random_cases - hits);
  // Misses and false hits apart: the liar's random disagreements are all false hits, named on stderr.
  const SuiteResult res = f.assembled(f.results);
  bool named = false;
  for (const std::string& line : res.stderr_lines)
    named = named || line.rfind("plane: liar: 0 misses (false negatives), ", 0) == 0;
  EXPECT_TRUE(named);
}

TEST(PlaneSuite, AThrowingCategoryFailsItsGroupsChecksWithTheReason) {
  std::vector<Category> cats = categories();
  cats[1].make = &broken_case;  // edge: the border group
  const Fixture f(cats);
  const auto c = f.checks(f.results);
  for (const char* e : {"core", "liar", "never"})
    for (const char* what : {"agreement", "t_error"}) {
      const Check& x = c.at(std::string("plane/") + e + "/" + what + "/border");
      EXPECT_FALSE(x.pass) << x.name;
      EXPECT_NE(x.reason.find("edge: case"), std::string::npos) << x.reason;
      EXPECT_NE(x.reason.find("broken generator"), std::string::npos) << x.reason;
    }
  EXPECT_TRUE(c.at("plane/core/agreement/random").pass);
  EXPECT_TRUE(c.at("plane/core/t_error/exact-geometry").pass);
  EXPECT_TRUE(c.at("plane/contact_time/midpoint/h=0.1").pass);
  const SuiteResult r = f.assembled(f.results);
  EXPECT_NE(r.markdown.find("Category `edge` failed: case"), std::string::npos);
  EXPECT_EQ(r.checks.size(), f.plan.checks.size());
}

TEST(PlaneSuite, AThrowingContactCellOrDropFailsWhatItFeeds) {
  const Fixture f;
  std::vector<io::Json> r = f.results;
  const ContactCell cell{0, 1, 1};  // midpoint, h = 0.02, k = 8
  r[case_index(f.plan.layout, {CaseGroup::ContactTime, contact_index(f.plan.layout, cell)})] = {{"error", "case 20 threw: a"}};
  r[case_index(f.plan.layout, {CaseGroup::Drop, 1})] = {{"error", "case 30 threw: b"}};
  const auto c = f.checks(r);
  EXPECT_TRUE(c.at("plane/contact_time/midpoint/h=0.1").pass);
  EXPECT_FALSE(c.at("plane/contact_time/midpoint/h=0.02").pass);
  EXPECT_EQ(c.at("plane/contact_time/midpoint/h=0.02").reason, "k = 8: case 20 threw: a");
  EXPECT_EQ(c.at("plane/drop/core_apex_rel_error").reason, "z0 = 1 m: case 30 threw: b");
  EXPECT_EQ(c.at("plane/drop/bullet_rigid_contact_time_error").reason, "z0 = 1 m: case 30 threw: b");
}

TEST(PlaneSuite, ADropThatNeverLandsFailsWithTheReason) {
  const Fixture f;
  std::vector<io::Json> r = f.results;
  io::Json& cell = r[case_index(f.plan.layout, {CaseGroup::ContactTime, 0})];
  cell["first_missing"] = 1;
  cell["contacts"] = 2;
  io::Json& drop = r[case_index(f.plan.layout, {CaseGroup::Drop, 0})];
  drop["apex_core"] = "nan";
  const auto c = f.checks(r);
  EXPECT_EQ(c.at("plane/contact_time/midpoint/h=0.1").reason, "k = 4: drop 1 made no contact within 10 s (2 of 3 did)");
  EXPECT_EQ(c.at("plane/drop/core_apex_rel_error").reason, "z0 = 0.2 m: core never touched the floor");
}

std::string q(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

TEST(PlaneSuite, EveryToleranceChangedSameChecksSameWork) {
  const auto dir = testing::temp_dir("plane-tolerances");
  const auto base = run_cli("suite plane --quick --out " + q(dir / "base"));
  ASSERT_EQ(base.code, 0) << base.err;
  const auto want = nlohmann::json::parse(testing::slurp(dir / "base" / "report.json"));
  ASSERT_FALSE(testing::check_names(want).empty());
  ASSERT_GT(testing::write_changed_tolerances(dir / "scaled.json", {"plane"}, [](double x) { return 1.37 * x; }), 0);
  const auto r = run_cli("suite plane --quick --tolerances " + q(dir / "scaled.json") + " --out " + q(dir / "scaled"));
  EXPECT_EQ(r.code, 1) << r.err;  // core's agreement bands start at 1.37: no share reaches them
  const auto got = nlohmann::json::parse(testing::slurp(dir / "scaled" / "report.json"));
  EXPECT_EQ(testing::check_names(got), testing::check_names(want));
  EXPECT_EQ(testing::data_without_timings(got), testing::data_without_timings(want)) << "other work";
  const auto& checks = got["suites"][0]["checks"];
  const auto& before = want["suites"][0]["checks"];
  for (std::size_t i = 0; i < checks.size(); ++i) {
    EXPECT_EQ(checks[i]["value"], before[i]["value"]) << checks[i]["name"];
    const std::string name = checks[i]["name"];
    if (name.rfind("plane/core/agreement/", 0) == 0) {
      EXPECT_FALSE(checks[i]["pass"].get<bool>()) << name;
    }
  }
  std::filesystem::remove_all(dir);
}

TEST(PlaneSuite, ShardsMergeIntoTheSameReport) {
  const auto dir = testing::temp_dir("plane-shards");
  ASSERT_EQ(run_cli("suite plane --quick --out " + q(dir / "all")).code, 0);
  for (int i = 0; i < 2; ++i) {
    const std::string shard = std::to_string(i);
    const auto r = run_cli("suite plane --quick --shard " + shard + "/2 --out " + q(dir / ("s" + shard)));
    ASSERT_EQ(r.code, 0) << r.err;
  }
  const auto m = run_cli("merge " + q(dir / "s0") + " " + q(dir / "s1") + " --out " + q(dir / "merged"));
  ASSERT_EQ(m.code, 0) << m.err;
  const auto all = nlohmann::json::parse(testing::slurp(dir / "all" / "report.json"));
  const auto merged = nlohmann::json::parse(testing::slurp(dir / "merged" / "report.json"));
  EXPECT_EQ(testing::check_names(merged), testing::check_names(all));
  EXPECT_EQ(testing::data_without_timings(merged), testing::data_without_timings(all));
  EXPECT_EQ(testing::slurp(dir / "merged" / "plane" / "disagreements.json"),
            testing::slurp(dir / "all" / "plane" / "disagreements.json"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido::suites::plane
