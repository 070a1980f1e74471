// The obstacles suite's declared checks: the set depends on the settings only (never on measured
// values or on the tolerance file's numbers), tightening a band flips a check, a case that threw or
// a value never produced fails with its reason.
#include "comparisons/io/source_dir.h"
#include "comparisons/suites/obstacles/check_plan.h"
#include "comparisons/suites/sweep.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace tecido::suites::obstacles {

namespace {

Tolerances file_tolerances() { return Tolerances::load(std::string(TECIDO_SOURCE_DIR) + "/data/tolerances.json"); }

/// The tolerance file with every number of the obstacles section multiplied by `factor`.
Tolerances scaled(double factor) {
  io::Json doc = file_tolerances().doc();
  for (auto& [key, value] : doc["obstacles"].items())
    if (value.is_number()) value = value.get<double>() * factor;
  return Tolerances(doc, "scaled");
}

std::vector<std::string> names(const CheckList& c) {
  std::vector<std::string> out;
  for (const Check& k : c.finish()) out.push_back(k.name);
  return out;
}

const Check& find(const std::vector<Check>& checks, const std::string& name) {
  auto it = std::find_if(checks.begin(), checks.end(), [&](const Check& c) { return c.name == name; });
  if (it == checks.end()) throw std::runtime_error("no check " + name);
  return *it;
}

Case named(const std::string& name) { return Case{name, nullptr}; }

io::Json drop_result(double t_core) {
  return {{"t_exact", num(0.5)},       {"t_core", num(t_core)},     {"apex_expected", num(0.64)},
          {"apex_core", num(0.64)},    {"apex_sampled", num(0.64)}, {"unstable", nullptr}};
}

}  // namespace

TEST(ObstaclesCheckPlan, TheCheckSetDependsOnTheSettingsOnly) {
  const Settings s = settings(false);
  const auto base = names(declare_checks(s, file_tolerances(), true));
  EXPECT_EQ(base, names(declare_checks(s, scaled(1.37), true)));
  EXPECT_EQ(base, names(declare_checks(s, scaled(0.0), true)));
  EXPECT_EQ(base, names(declare_checks(settings(true), file_tolerances(), true)));
  // 2 sphere drop + 2 slide + 4 rest + 20 fast + 5 thin-box tunnelling + 4 block inside + 2 edges-on
  // + 3 matched block comparison, and 3 Bullet onsets in the reference build.
  EXPECT_EQ(base.size(), 42u + 3u);
  EXPECT_EQ(names(declare_checks(s, file_tolerances(), false)).size(), 42u);
}

TEST(ObstaclesCheckPlan, EveryDeclaredCheckWithoutAValueFailsNotProduced) {
  const auto checks = declare_checks(settings(true), file_tolerances(), false).finish();
  for (const Check& c : checks) {
    EXPECT_FALSE(c.pass) << c.name;
    EXPECT_FALSE(c.reason.empty()) << c.name;
  }
}

TEST(ObstaclesCheckPlan, TighteningABandFlipsTheCheckToFailed) {
  const Settings s = settings(true);
  const double error = 2e-7;  // a contact time 2e-7 s off: 2e-4 steps of 1 ms
  CheckList loose = declare_checks(s, scaled(1.0), false);
  record(loose, s, named("sphere-drop"), drop_result(0.5 + error));
  EXPECT_TRUE(find(loose.finish(), "obstacles/sphere-drop/contact_time_error").pass);
  CheckList tight = declare_checks(s, scaled(0.1), false);  // band 1e-4 steps = 1e-7 s
  record(tight, s, named("sphere-drop"), drop_result(0.5 + error));
  const std::vector<Check> done = tight.finish();
  const Check& c = find(done, "obstacles/sphere-drop/contact_time_error");
  EXPECT_FALSE(c.pass);
  EXPECT_NEAR(c.value, error, 1e-15);
}

TEST(ObstaclesCheckPlan, ACaseThatThrewOrWentUnstableFailsItsOwnChecksWithTheReason) {
  const Settings s = settings(true);
  CheckList checks = declare_checks(s, file_tolerances(), false);
  record(checks, s, named("fast/thin-box/h=10"), io::Json{{"error", "boom"}});
  io::Json unstable = drop_result(0.5);
  unstable["unstable"] = 17;
  record(checks, s, named("sphere-drop"), unstable);
  const auto done = checks.finish();
  EXPECT_NE(find(done, "obstacles/fast/thin-box/h=10/steps_inside").reason.find("boom"), std::string::npos);
  EXPECT_NE(find(done, "obstacles/fast/thin-box/h=10/tunnelled").reason.find("boom"), std::string::npos);
  EXPECT_NE(find(done, "obstacles/sphere-drop/apex_rel_error").reason.find("unstable at step 17"), std::string::npos);
  EXPECT_EQ(find(done, "obstacles/fast/thin-box/h=1/steps_inside").reason, "not produced");
}

/// An edges-off block run's result as record_matched reads it: all four insets `inset`.
io::Json block_run(double spacing, double inset, double end_depth, int end_through, int across) {
  return io::Json{{"spacing", num(spacing)},   {"insets", {num(inset), num(inset), num(inset), num(inset)}},
                  {"end_depth", num(end_depth)}, {"end_through", end_through},
                  {"across", across},           {"unstable", nullptr}};
}

/// record_matched on the two runs, the three checks by name.
std::vector<Check> matched(const io::Json& coarse, const io::Json& fine) {
  const Settings s = settings(true);
  io::Json by_name;
  by_name[block_name(s.block_sides[0], false)] = coarse;
  by_name[block_name(s.block_sides[1], false)] = fine;
  CheckList checks = declare_checks(s, file_tolerances(), false);
  record_matched(checks, s, by_name);
  std::vector<Check> out;
  for (const char* k : {"inset_difference", "depth_per_spacing_ratio", "cut_share_ratio"})
    out.push_back(find(checks.finish(), std::string("obstacles/block/matched/") + k));
  return out;
}

TEST(ObstaclesCheckPlan, MatchedBlockChecksOnWorkedCases) {
  // 121 particles at spacing 0.1 sink 30 mm (0.3 spacings), 100 of 160 springs across the outline
  // cut; 484 at 0.05 sink 15 mm (0.3 spacings), 200 of 340 cut: (0.3 / 0.3) = 1 and
  // (200 / 340) / (100 / 160) = 0.941..., both within the file's 25% of 1.
  const io::Json coarse = block_run(0.1, 0.5, 0.03, 100, 160);
  auto ok = matched(coarse, block_run(0.05, 0.5, 0.015, 200, 340));
  EXPECT_TRUE(ok[0].pass);
  EXPECT_EQ(ok[0].value, 0.0);
  EXPECT_TRUE(ok[1].pass);
  EXPECT_NEAR(ok[1].value, 1.0, 1e-12);
  EXPECT_TRUE(ok[2].pass);
  EXPECT_NEAR(ok[2].value, (200.0 / 340.0) / (100.0 / 160.0), 1e-12);
  // The finer cloth 10 mm deep: shallower in metres (the old "depth ratio at most 1" held, 1/3),
  // but 0.2 spacings against 0.3, 0.667: more than spacing explains, the check fails.
  auto shallow = matched(coarse, block_run(0.05, 0.5, 0.010, 200, 340));
  EXPECT_FALSE(shallow[1].pass);
  EXPECT_NEAR(shallow[1].value, 2.0 / 3.0, 1e-12);
  // 20 mm: 0.4 spacings, 1.333: relatively deeper, fails the other way; so does a share that falls.
  auto deep = matched(coarse, block_run(0.05, 0.5, 0.020, 100, 340));
  EXPECT_FALSE(deep[1].pass);
  EXPECT_NEAR(deep[1].value, 4.0 / 3.0, 1e-12);
  EXPECT_FALSE(deep[2].pass);
  EXPECT_NEAR(deep[2].value, (100.0 / 340.0) / (100.0 / 160.0), 1e-12);
  // The old scenes' placement (0.5 against 0.75 spacings): the comparison's premise fails.
  auto placed = matched(coarse, block_run(0.05, 0.75, 0.015, 200, 340));
  EXPECT_FALSE(placed[0].pass);
  EXPECT_NEAR(placed[0].value, 0.25, 1e-15);
}

TEST(ObstaclesCheckPlan, MatchedBlockChecksFailWithAReasonOnBadRuns) {
  const io::Json fine = block_run(0.05, 0.5, 0.015, 200, 340);
  // Nothing through the coarser cloth: the ratios are not finite, and fail.
  auto none = matched(block_run(0.1, 0.5, 0.0, 0, 160), fine);
  EXPECT_FALSE(none[1].pass);
  EXPECT_FALSE(none[2].pass);
  EXPECT_FALSE(none[1].reason.empty());
  for (const io::Json& bad : {io::Json{{"error", "no cloth"}}, io::Json{{"unstable", 12}}}) {
    auto failed = matched(block_run(0.1, 0.5, 0.03, 100, 160), bad);
    for (const Check& c : failed) {
      EXPECT_FALSE(c.pass) << c.name;
      EXPECT_NE(c.reason.find(bad.contains("error") ? "no cloth" : "unstable"), std::string::npos) << c.reason;
    }
  }
}

}  // namespace tecido::suites::obstacles
