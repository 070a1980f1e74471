// `tecido run` and `tecido plane` from outside: the JSON contract, overrides, and the observed
// order of each integrator on an oscillator scene written here (not one of data/scenes).
#include "tests/support/cli_runner.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>

namespace tecido {
namespace {

using nlohmann::json;
using testing::run_cli;

// Two free particles joined by a spring (ks = 9, l = 1, m = 1 each): the separation obeys
// d'' = -(2 ks / m)(d - l), omega = sqrt(18); the centre of mass drifts at 0.25 m/s.
const char* kTwoBody = R"({"dt":0.01,"steps":100,
 "particles":[{"position":[0,0,0],"velocity":[0.5,0,0],"mass":1.0},{"position":[1.2,0,0],"velocity":[0,0,0],"mass":1.0}],
 "springs":[{"i":0,"j":1,"stiffness":9.0,"rest_length":1.0}]})";

double two_body_error(const std::string& scene, const char* integ, double h) {
  const long long steps = std::llround(1.0 / h);
  char args[512];
  std::snprintf(args, sizeof args, "run '%s' --json --integrator %s --dt %.17g --steps %lld", scene.c_str(), integ, h, steps);
  const auto r = run_cli(args);
  EXPECT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  const double t = j["time"].get<double>();
  const double w = std::sqrt(18.0);
  // d(t) = l + 0.2 cos(w t) - (0.5 / w) sin(w t): d(0) = 1.2, d'(0) = -0.5.
  const double d = 1.0 + 0.2 * std::cos(w * t) - 0.5 / w * std::sin(w * t);
  const double xa = j["particles"][0]["x"][0].get<double>();
  const double xb = j["particles"][1]["x"][0].get<double>();
  const double com = 0.6 + 0.25 * t;
  return std::abs(xb - xa - d) + std::abs(0.5 * (xa + xb) - com);
}

TEST(CliRun, ObservedOrderFromOutside) {
  const auto dir = testing::temp_dir("order");
  const std::string scene = (dir / "two_body.json").string();
  testing::write_text(scene, kTwoBody);
  struct C {
    const char* name;
    double order, h;
  } cases[] = {{"euler", 1, 0.0005}, {"symplectic", 1, 0.0005}, {"midpoint", 2, 0.004}, {"rk4", 4, 0.02}};
  for (const C& c : cases) {
    const double e1 = two_body_error(scene, c.name, c.h);
    const double e2 = two_body_error(scene, c.name, c.h / 2);
    EXPECT_NEAR(std::log2(e1 / e2), c.order, 0.15) << c.name << " e1=" << e1 << " e2=" << e2;
  }
  std::filesystem::remove_all(dir);
}

TEST(CliRun, JsonContractAndOutDir) {
  const auto dir = testing::temp_dir("contract");
  const std::string scene = (dir / "s.json").string();
  testing::write_text(scene, kTwoBody);
  const auto r = run_cli("run '" + scene + "' --json --out '" + (dir / "out").string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["status"], "ok");
  EXPECT_TRUE(j["unstable_at_step"].is_null());
  EXPECT_EQ(j["steps"], 100);
  EXPECT_NEAR(j["time"].get<double>(), 1.0, 1e-12);
  ASSERT_EQ(j["particles"].size(), 2u);
  EXPECT_EQ(j["particles"][0]["x"].size(), 3u);
  EXPECT_EQ(j["particles"][0]["v"].size(), 3u);
  const json written = json::parse(testing::slurp(dir / "out" / "result.json"));
  EXPECT_EQ(written["particles"], j["particles"]);  // 17 digits: bit-identical round trip
  std::filesystem::remove_all(dir);
}

TEST(CliRun, UnstableRunIsReportedNotCrashed) {
  const auto dir = testing::temp_dir("unstable");
  const std::string scene = (dir / "s.json").string();
  testing::write_text(scene, R"({"integrator":"euler","dt":0.5,"steps":100000,
    "particles":[{"position":[0,0,0],"pinned":true},{"position":[1.5,0,0],"mass":0.001}],
    "springs":[{"i":0,"j":1,"stiffness":1e6,"rest_length":1.0}]})");
  const auto r = run_cli("run '" + scene + "' --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["status"], "unstable");
  EXPECT_GT(j["unstable_at_step"].get<long long>(), 0);
  EXPECT_EQ(j["instability"]["particle"], 1);
  std::filesystem::remove_all(dir);
}

/// The number after `marker` in `text` (NaN when absent).
double number_after(const std::string& text, const std::string& marker) {
  const auto pos = text.find(marker);
  return pos == std::string::npos ? NAN : std::strtod(text.c_str() + pos + marker.size(), nullptr);
}

// A step too large for the spring: still exit 0 and the result, and one line on stderr with the
// step the spring allows. Particles of 1 and 3 kg on 100 N/m: omega = sqrt(100 (1 + 1/3)), and
// symplectic Euler is stable for h omega <= 2 (RK4: 2 sqrt 2); dt = 0.5 s is h omega = 5.8.
TEST(CliRun, UnstableRunHintsAtTheStepTheStiffestSpringAllows) {
  const auto dir = testing::temp_dir("hint");
  const std::string scene = (dir / "s.json").string();
  testing::write_text(scene, R"({"integrator":"symplectic","dt":0.5,"steps":2000,
    "particles":[{"position":[0,0,0],"mass":1},{"position":[1.5,0,0],"mass":3}],
    "springs":[{"i":0,"j":1,"stiffness":100,"rest_length":1}]})");
  const double omega = std::sqrt(100.0 * (1.0 + 1.0 / 3.0));
  for (const auto& [integrator, limit] : {std::pair<std::string, double>{"symplectic", 2.0}, {"rk4", 2.0 * std::sqrt(2.0)}}) {
    const auto r = run_cli("run '" + scene + "' --json --integrator " + integrator);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(json::parse(r.out)["status"], "unstable");
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind("tecido: hint: " + integrator + " is stable on the stiffest spring (particles 0 and 1, k = 100 N/m", 0), 0u)
        << r.err;
    EXPECT_NEAR(number_after(r.err, "for dt <= "), limit / omega, 1e-5 * limit / omega) << r.err;
    EXPECT_NE(r.err.find("this run used dt = 0.5 s"), std::string::npos) << r.err;
  }
  // The same line without --json; none when the step is small enough (h omega = 0.12).
  const auto text = run_cli("run '" + scene + "'");
  EXPECT_NE(text.err.find("tecido: hint: symplectic is stable"), std::string::npos) << text.err;
  const auto fine = run_cli("run '" + scene + "' --json --dt 0.01 --steps 100");
  ASSERT_EQ(fine.code, 0) << fine.err;
  EXPECT_EQ(json::parse(fine.out)["status"], "ok");
  EXPECT_EQ(fine.err, "");
  std::filesystem::remove_all(dir);
}

TEST(CliPlane, CasesFileContract) {
  const auto dir = testing::temp_dir("plane");
  const std::string cases = (dir / "cases.json").string();
  testing::write_text(cases, R"({"cases":[
    {"id":"through","label":"ignored","plane":{"position":[0,0,0],"normal":[0,0,1],"forward":[1,0,0],"half_extents":[1,1]},"from":[0,0,1],"to":[0,0,-3]},
    {"id":"outside","plane":{"position":[0,0,0],"normal":[0,0,1],"forward":[1,0,0],"half_extents":[1,1]},"from":[2,0,1],"to":[2,0,-1]}]})");
  const auto r = run_cli("plane --cases '" + cases + "' --engines core --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  ASSERT_EQ(j["results"].size(), 2u);
  EXPECT_EQ(j["results"][0]["id"], "through");
  EXPECT_EQ(j["results"][0]["core"]["hit"], true);
  EXPECT_DOUBLE_EQ(j["results"][0]["core"]["t"].get<double>(), 0.25);
  EXPECT_EQ(j["results"][1]["core"]["hit"], false);
  EXPECT_TRUE(j["results"][1]["core"]["t"].is_null());
  std::filesystem::remove_all(dir);
}

TEST(CliHelp, EverySubcommandHasHelp) {
  for (const char* sub : {"run", "plane"}) {
    const auto r = run_cli(std::string(sub) + " --help");
    EXPECT_EQ(r.code, 0) << sub;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << sub;
  }
}

}  // namespace
}  // namespace tecido
