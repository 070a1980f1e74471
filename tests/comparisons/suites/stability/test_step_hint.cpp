// The step an unstable run's hint names (comparisons/suites/stability/step_hint.h), against the
// closed forms written out here: omega = sqrt(k (1/m_i + 1/m_j)); symplectic Euler stable for
// h omega <= 2, RK4 for h omega <= 2 sqrt 2; explicit Euler and midpoint grow by |R| per step,
// |R|^2 = 1 + c^2 and 1 + c^4 / 4 (c = h omega), so a run of duration T grows by
// |R|^(T omega / c), which the hint holds to 1000 (the suite's amplitude bound).
#include "comparisons/io/scene_json.h"
#include "comparisons/suites/stability/step_hint.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <functional>

namespace tecido {
namespace {

using suites::stability::stiffest_spring_step;

/// Particles 0 (1 kg) and 1 (3 kg) on a spring of 100 N/m; a stiffer spring between two pinned
/// particles (2, 3) that cannot oscillate; a softer one from pinned 2 to 0. dt 0.5 s, 2000 steps.
Scene hint_scene(const char* integrator) {
  const std::string text = std::string(R"({"integrator":")") + integrator + R"(","dt":0.5,"steps":2000,
   "particles":[{"position":[0,0,0],"mass":1},{"position":[1.5,0,0],"mass":3},
                {"position":[0,2,0],"pinned":true},{"position":[1,2,0],"pinned":true}],
   "springs":[{"i":0,"j":1,"stiffness":100,"rest_length":1},{"i":2,"j":3,"stiffness":1e6},
              {"i":2,"j":0,"stiffness":50}]})";
  return io::scene_from_json(io::parse_json_text(text, "hint.json"), "hint.json");
}

const double kOmega = std::sqrt(100.0 * (1.0 / 1.0 + 1.0 / 3.0));  // the 0-1 spring; 2-0: sqrt(50) is softer

/// The c in (0, 1] at which (T omega / c) ln|R(c)| = ln 1000, by this test's own bisection.
double growth_root(const std::function<double(double)>& log_r, double t_omega) {
  double lo = 1e-12, hi = 1.0;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (t_omega / mid * log_r(mid) > std::log(1000.0) ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(StepHint, SymplecticAndRk4FromTheStiffestFreeSpring) {
  const auto s = stiffest_spring_step(hint_scene("symplectic"));
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->i, 0);
  EXPECT_EQ(s->j, 1);
  EXPECT_NEAR(s->omega, kOmega, 1e-12 * kOmega);
  EXPECT_TRUE(s->bounded);
  EXPECT_NEAR(s->dt_max, 2.0 / kOmega, 1e-12);
  const auto r = stiffest_spring_step(hint_scene("rk4"));
  ASSERT_TRUE(r.has_value());
  EXPECT_NEAR(r->dt_max, 2.0 * std::sqrt(2.0) / kOmega, 1e-12);
}

TEST(StepHint, EulerAndMidpointFromTheRunsGrowth) {
  const double t_omega = 2000 * 0.5 * kOmega;
  const auto e = stiffest_spring_step(hint_scene("euler"));
  ASSERT_TRUE(e.has_value());
  EXPECT_FALSE(e->bounded);
  EXPECT_EQ(e->growth_bound, 1000.0);
  const double ce = growth_root([](double c) { return 0.5 * std::log1p(c * c); }, t_omega);
  EXPECT_NEAR(e->dt_max, ce / kOmega, 1e-6 * ce / kOmega);
  // Small c: ln|R| ~ c^2 / 2, so c ~ 2 ln 1000 / (T omega).
  EXPECT_NEAR(ce, 2.0 * std::log(1000.0) / t_omega, 1e-3 * ce);
  const auto m = stiffest_spring_step(hint_scene("midpoint"));
  ASSERT_TRUE(m.has_value());
  const double cm = growth_root([](double c) { return 0.5 * std::log1p(c * c * c * c / 4.0); }, t_omega);
  EXPECT_NEAR(m->dt_max, cm / kOmega, 1e-6 * cm / kOmega);
  // The line names the growth step and, as the way out, symplectic Euler's stable step 2 / omega.
  const std::string line = suites::stability::step_hint_line(*e, hint_scene("euler"));
  EXPECT_EQ(line.rfind("tecido: hint: euler amplifies an undamped spring at every step; on the stiffest spring (particles 0 "
                       "and 1, k = 100 N/m, omega = sqrt(k (1/m_i + 1/m_j)) = 11.547 rad/s) it grows at most 1000x over "
                       "this run's 1000 s for dt <= ",
                       0),
            0u)
      << line;
  const auto sym = line.find("(symplectic is stable for dt <= ");
  ASSERT_NE(sym, std::string::npos) << line;
  EXPECT_NEAR(std::strtod(line.c_str() + sym + 32, nullptr), 2.0 / kOmega, 1e-5 * 2.0 / kOmega) << line;
  EXPECT_NE(line.find("this run used dt = 0.5 s"), std::string::npos) << line;
}

TEST(StepHint, NoneWithoutASpringThatCanOscillate) {
  const Scene no_springs = io::scene_from_json(
      io::parse_json_text(R"({"dt":0.1,"steps":1,"particles":[{"position":[0,0,0],"mass":1}]})", "n.json"), "n.json");
  EXPECT_FALSE(stiffest_spring_step(no_springs).has_value());
  const Scene pinned = io::scene_from_json(
      io::parse_json_text(R"({"dt":0.1,"steps":1,"particles":[{"position":[0,0,0],"pinned":true},
        {"position":[1,0,0],"pinned":true},{"position":[2,0,0],"mass":1}],
        "springs":[{"i":0,"j":1,"stiffness":5},{"i":1,"j":2,"stiffness":0}]})", "p.json"), "p.json");
  EXPECT_FALSE(stiffest_spring_step(pinned).has_value());
}

}  // namespace
}  // namespace tecido
