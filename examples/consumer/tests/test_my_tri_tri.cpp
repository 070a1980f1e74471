// The user's triangle test against tecido's exact referee on the tritri suite's families.
#include "my_engine.h"

#include <gtest/gtest.h>
#include <tecido/harness.h>

#include <algorithm>
#include <iostream>

namespace {

namespace th = tecido::harness;

th::QueryReport on_families(const tecido_engine& engine, std::vector<std::string> families) {
  th::CaseOptions o;
  o.families = std::move(families);
  const th::QueryReport r = th::check_tri_tri(engine, th::tri_tri_cases(o));
  for (const th::FamilyTally& f : r.families)
    std::cout << r.engine << " on " << f.family << ": " << f.disagreements << " of " << f.queries
              << " disagree with the referee\n";
  return r;
}

TEST(MyTriTri, AgreesWithTheRefereeOnRandomPairs) {
  const th::QueryReport r = on_families(my_tri_tri_engine(), {"random"});
  EXPECT_EQ(r.queries, 100000u);
  EXPECT_EQ(r.disagreements, 0u) << r.json();
}

TEST(MyTriTri, AdversarialFamiliesFindItsCoplanarGap) {
  // The user's test answers 0 for coplanar pairs (Moller-Trumbore's parallel case): the coplanar
  // family must show misses; the touching, shared-vertex, sliver and offset families, which it
  // handles, must agree with the referee everywhere.
  const th::QueryReport r = on_families(my_tri_tri_engine(), {});
  for (const th::FamilyTally& f : r.families) {
    if (f.family == "coplanar") EXPECT_GT(f.disagreements, 0u);
    if (f.family == "touch-vertex" || f.family == "touch-edge" || f.family == "shared-vertex" ||
        f.family == "sliver" || f.family == "offset")
      EXPECT_EQ(f.disagreements, 0u) << f.family;
  }
  EXPECT_GT(r.misses, 0u);
  ASSERT_FALSE(r.first_disagreements.empty());
  EXPECT_NE(r.first_disagreements.front().id.find('/'), std::string::npos);  // "<family>/<k>"
}

TEST(MyTriTri, ABoundingBoxTestIsCaught) {
  // Deliberately wrong: boxes overlap -> "intersecting". The referee must see its false hits.
  tecido_engine boxes{};
  boxes.name = "boxes-only";
  boxes.tri_tri = [](const double a[9], const double b[9]) {
    for (int c = 0; c < 3; ++c) {
      const double alo = std::min({a[c], a[3 + c], a[6 + c]}), ahi = std::max({a[c], a[3 + c], a[6 + c]});
      const double blo = std::min({b[c], b[3 + c], b[6 + c]}), bhi = std::max({b[c], b[3 + c], b[6 + c]});
      if (ahi < blo || bhi < alo) return 0;
    }
    return 1;
  };
  const th::QueryReport r = on_families(boxes, {"random"});
  EXPECT_GT(r.false_hits, 0u);
  EXPECT_EQ(r.misses, 0u);  // a box test never misses
}

}  // namespace
