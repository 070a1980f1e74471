// The user's cloth integrator against the order it claims: tecido's order suite fits the observed
// order of the error on its analytic problems and checks it against the claim.
#include "my_engine.h"

#include <gtest/gtest.h>
#include <tecido/harness.h>

#include <iostream>

namespace {

namespace th = tecido::harness;

th::Report order_suite(const tecido_engine& engine) {
  const th::Report r = th::run_suites({"order"}, {engine});
  for (const th::Check& c : r.checks_with(engine.name))
    std::cout << c.name << ": " << c.value << " in [" << c.lo << ", " << c.hi << "] " << (c.pass ? "pass" : "FAIL")
              << (c.reason.empty() ? "" : " (" + c.reason + ")") << "\n";
  return r;
}

TEST(MyCloth, SymplecticEulerShowsTheFirstOrderItClaims) {
  const th::Report r = order_suite(my_cloth_engine("my-cloth", 1.0));
  const auto mine = r.checks_with("my-cloth");
  ASSERT_FALSE(mine.empty());  // the suite declared checks for the engine
  for (const th::Check& c : mine) EXPECT_TRUE(c.pass) << c.name << " = " << c.value << " " << c.reason;
}

TEST(MyCloth, AClaimOfSecondOrderIsCaught) {
  // Deliberately wrong: the same first-order integrator claiming order 2.
  const th::Report r = order_suite(my_cloth_engine("my-cloth-claims-2", 2.0));
  const auto mine = r.checks_with("my-cloth-claims-2");
  ASSERT_FALSE(mine.empty());
  std::size_t failed = 0;
  for (const th::Check& c : mine) failed += c.pass ? 0 : 1;
  EXPECT_GT(failed, 0u);
  EXPECT_GT(r.failed(), 0u);
}

}  // namespace
