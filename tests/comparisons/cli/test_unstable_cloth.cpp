// A cloth blown up on purpose (docs/design.md section 4: "NaN or Inf in a state ends the run as
// unstable at that step"): explicit Euler, stiff springs, a big step. Explicit Euler amplifies
// every spring mode by at least sqrt(1 + (w h)^2) per step; here w h = sqrt(ks/m) h ~ 10, so
// the state overflows within a few hundred steps. Checked from outside, through the CLI: the
// report says "unstable", the step, the particle and the quantity, and they are true.
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace tecido {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::run_cli;

// 8 x 8 cloth hanging from two pins (row 0, columns 0 and 7 = particles 0 and 7), 0.01 kg per
// interior particle, ks = 1e4 N/m: w = sqrt(ks/m) = 1000 rad/s, h = 0.01 s.
const char* kStiffEulerCloth = R"({"integrator":"euler","dt":0.01,"steps":2000,"gravity":[0,0,-9.81],
 "cloth":{"rows":8,"cols":8,"spacing":0.1,"origin":[0,0,1],"axis_u":[1,0,0],"axis_v":[0,0,-1],
          "total_mass":0.64,"stiffness_b":1e4,"stiffness_a":1e4,"pins":[[0,0],[0,7]]}})";

bool all_finite(const json& v3) {
  for (const auto& c : v3)
    if (!c.is_number() || !std::isfinite(c.get<double>())) return false;
  return v3.size() == 3;
}

TEST(UnstableCloth, ExplicitEulerBlowUpIsReportedWithStepParticleAndQuantity) {
  const auto dir = testing::temp_dir("unstable-cloth");
  const std::string scene = (dir / "stiff.json").string();
  testing::write_text(scene, kStiffEulerCloth);
  const auto r = run_cli("run '" + scene + "' --json --out '" + (dir / "out").string() + "'");
  ASSERT_EQ(r.code, 0) << "an unstable run is a result, not an error: " << r.err;
  const json j = json::parse(r.out);  // non-finite numbers are printed as null: still valid JSON
  EXPECT_EQ(j["status"], "unstable");
  ASSERT_TRUE(j["unstable_at_step"].is_number_integer());
  const long long at = j["unstable_at_step"].get<long long>();
  EXPECT_GT(at, 1);
  EXPECT_LT(at, 2000);
  EXPECT_EQ(j["steps"], at) << "the run stops at the step that went bad";
  EXPECT_NEAR(j["time"].get<double>(), at * 0.01, 1e-9);
  ASSERT_TRUE(j["instability"].is_object());
  EXPECT_EQ(j["instability"]["step"], at);
  const int p = j["instability"]["particle"].get<int>();
  ASSERT_EQ(j["particles"].size(), 64u);
  ASSERT_GE(p, 0);
  ASSERT_LT(p, 64);
  EXPECT_NE(p, 0) << "pinned particles never move";
  EXPECT_NE(p, 7) << "pinned particles never move";
  // Explicit Euler moves x with the old, finite v, so the velocity (v += h F/m, F ~ ks x) is what
  // overflows first: every position is still finite, the named particle's velocity is not.
  EXPECT_EQ(j["instability"]["quantity"], "velocity");
  EXPECT_FALSE(all_finite(j["particles"][p]["v"])) << j["particles"][p];
  for (std::size_t i = 0; i < 64; ++i) EXPECT_TRUE(all_finite(j["particles"][i]["x"])) << "particle " << i;

  // The step before was still finite everywhere: the reported step is the first bad one.
  const auto before = run_cli("run '" + scene + "' --json --steps " + std::to_string(at - 1));
  ASSERT_EQ(before.code, 0) << before.err;
  const json b = json::parse(before.out);
  EXPECT_EQ(b["status"], "ok");
  EXPECT_TRUE(b["unstable_at_step"].is_null());
  for (const auto& q : b["particles"]) EXPECT_TRUE(all_finite(q["x"]) && all_finite(q["v"]));

  // --out writes the same result; the plain output names step, particle and quantity in words.
  const json written = json::parse(testing::slurp(dir / "out" / "result.json"));
  EXPECT_EQ(written["status"], "unstable");
  EXPECT_EQ(written["instability"], j["instability"]);
  const auto text = run_cli("run '" + scene + "'");
  ASSERT_EQ(text.code, 0);
  EXPECT_NE(text.out.find("status unstable"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("unstable at step " + std::to_string(at) + ": particle " + std::to_string(p) + " velocity"),
            std::string::npos)
      << text.out;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tecido
