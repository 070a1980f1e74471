// The user's continuous-collision test against tecido's exact referee on the ccd suite's families.
#include "my_engine.h"

#include <gtest/gtest.h>
#include <tecido/harness.h>

#include <iostream>

namespace {

namespace th = tecido::harness;

th::QueryReport on_families(const tecido_engine& engine, std::vector<std::string> families) {
  th::CaseOptions o;
  o.families = std::move(families);
  const th::QueryReport r = th::check_ccd(engine, th::ccd_cases(o));
  for (const th::FamilyTally& f : r.families)
    std::cout << r.engine << " on " << f.family << ": " << f.disagreements << " of " << f.queries
              << " disagree with the referee\n";
  std::cout << r.engine << ": latest time of impact " << r.max_late_toi << " after the exact one\n";
  return r;
}

TEST(MyCcd, AgreesWithTheRefereeOnTransversalCrossings) {
  const th::QueryReport r = on_families(my_ccd_engine(), {"vertex-face/crossing", "edge-edge/crossing"});
  EXPECT_EQ(r.disagreements, 0u) << r.json();
  EXPECT_LE(r.max_late_toi, 1e-12);  // bisection to 1e-13
}

TEST(MyCcd, AdversarialFamiliesFindItsMisses) {
  const th::QueryReport r = on_families(my_ccd_engine(), {});
  EXPECT_GT(r.misses, 0u);  // coplanar and tangential motion between samples
}

TEST(MyCcd, ADiscreteTestAtTheEndOfTheStepIsCaught) {
  // Deliberately wrong: only the end of the step is looked at, so a vertex that passes through a
  // face within the step (tunnelling) is missed.
  tecido_engine at_end{};
  at_end.name = "end-of-step";
  at_end.ccd_vertex_face = [](const double* /*t0*/, const double* t1, double* toi) {
    return my_ccd_vertex_face(t1, t1, toi);  // a motionless query at the end position
  };
  const th::QueryReport r = on_families(at_end, {"vertex-face/crossing"});
  EXPECT_GT(r.misses, 0u);
}

}  // namespace
