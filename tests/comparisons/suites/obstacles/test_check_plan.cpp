// The obstacles suite's declared checks: the set depends on the settings only (never on measured
// values or on the tolerance file's numbers), tightening a band flips a check, a case that threw or
// a value never produced fails with its reason.
#include "comparisons/suites/obstacles/check_plan.h"
#include "comparisons/suites/obstacles/obstacles_report.h"
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
  // + 2 seed direction, and 3 Bullet onsets in the reference build.
  EXPECT_EQ(base.size(), 41u + 3u);
  EXPECT_EQ(names(declare_checks(s, file_tolerances(), false)).size(), 41u);
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

TEST(ObstaclesCheckPlan, TheSeedsDirectionComesFromBothEdgesOffRuns) {
  const Settings s = settings(true);
  auto run = [](int through, int springs, double depth) {
    return io::Json{{"max_through", through}, {"springs", springs}, {"max_spring_depth", num(depth)}, {"unstable", nullptr}};
  };
  io::Json by_name;
  by_name[block_name(s.block_sides[0], false)] = run(100, 400, 0.04);
  by_name[block_name(s.block_sides[1], false)] = run(150, 1800, 0.01);
  CheckList checks = declare_checks(s, file_tolerances(), false);
  record_direction(checks, s, by_name);
  const auto done = checks.finish();
  // (150 / 1800) / (100 / 400) = 1/3; 0.01 / 0.04 = 1/4.
  EXPECT_NEAR(find(done, "obstacles/block/seed_direction/share_ratio").value, 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(find(done, "obstacles/block/seed_direction/depth_ratio").value, 0.25, 1e-15);
  by_name[block_name(s.block_sides[1], false)] = io::Json{{"error", "no cloth"}};
  CheckList failed = declare_checks(s, file_tolerances(), false);
  record_direction(failed, s, by_name);
  EXPECT_NE(find(failed.finish(), "obstacles/block/seed_direction/depth_ratio").reason.find("no cloth"),
            std::string::npos);
}

TEST(ObstaclesReport, SeedDirectionComparesFramesWhereEitherClothCutsTheBlock) {
  // Frames [t, count, depth]: both zero (skipped), fewer, more, equal.
  const io::Json coarse = io::Json::array({{0.1, 0, 0.0}, {0.2, 10, 0.0}, {0.3, 4, 0.0}, {0.4, 5, 0.0}});
  const io::Json fine = io::Json::array({{0.1, 0, 0.0}, {0.2, 3, 0.0}, {0.3, 9, 0.0}, {0.4, 5, 0.0}});
  const Direction d = seed_direction(coarse, fine);
  EXPECT_EQ(d.frames, 3);
  EXPECT_EQ(d.fewer, 1);
  EXPECT_EQ(d.more, 1);
}

}  // namespace tecido::suites::obstacles
