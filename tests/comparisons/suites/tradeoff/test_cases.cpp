// The tradeoff suite's case indexing (comparisons/suites/tradeoff/cases.h), the reference's
// estimate from planted untimed runs (reference_solution.h) and the points made of planted case
// results (points.h).
#include "comparisons/suites/tradeoff/cases.h"

#include "comparisons/suites/sweep.h"
#include "comparisons/suites/tradeoff/points.h"
#include "comparisons/suites/tradeoff/reference_solution.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::suites::tradeoff {
namespace {

TEST(TradeoffCases, IndexingWalksSizesUntimedThenEngineMajorPoints) {
  const CaseLayout l = case_layout({{16, 3}, {32, 2}}, 4);
  ASSERT_EQ(l.first, (std::vector<std::size_t>{0, 5 + 12}));
  EXPECT_EQ(l.cases, 5 + 12 + 5 + 8u);
  for (std::size_t k = 0; k < l.cases; ++k) {
    const CaseIndex c = l.locate(k);
    const std::size_t back = c.timed ? l.point_case(c.size, c.engine, c.step) : l.untimed_case(c.size, c.untimed);
    EXPECT_EQ(back, k);
  }
  const CaseIndex a = l.locate(4);
  EXPECT_FALSE(a.timed);
  EXPECT_EQ(a.untimed, Untimed::NudgedOutOfPlane);
  const CaseIndex b = l.locate(5 + 3 * 2 + 1);  // size 0, engine 2, step 1
  EXPECT_TRUE(b.timed);
  EXPECT_EQ(b.size, 0u);
  EXPECT_EQ(b.engine, 2u);
  EXPECT_EQ(b.step, 1u);
  const CaseIndex c = l.locate(17 + 5 + 7);  // size 1, engine 3, step 1
  EXPECT_EQ(c.size, 1u);
  EXPECT_EQ(c.engine, 3u);
  EXPECT_EQ(c.step, 1u);
  EXPECT_THROW(l.locate(l.cases), std::out_of_range);
}

std::vector<Vec3> shifted(double dz) { return {Vec3(0, 0, dz), Vec3(1, 0, dz)}; }

TEST(TradeoffReference, EstimateFromPlantedRuns) {
  // Reference at 0, confirmation 15e-9 m off: estimated error 1e-9; RK4 at h_min 16 x the
  // confirmation's distance: observed order 4. Probes: in-plane 2e-12 m off for a 1e-12 m nudge.
  const Settings s;
  std::vector<std::optional<std::vector<Vec3>>> u = {shifted(0), shifted(15e-9), shifted(0.5), shifted(0.5 + 2e-12),
                                                     shifted(0.5 + 3e-6)};
  const ReferenceEstimate e = estimate_reference(u, "", 16 * 15e-9, 1e-4, s);
  EXPECT_TRUE(e.failure.empty());
  EXPECT_NEAR(e.difference, 15e-9, 1e-22);
  EXPECT_NEAR(e.error, 1e-9, 1e-21);
  EXPECT_NEAR(e.order, 4.0, 1e-9);
  EXPECT_NEAR(e.conditioning_in, 2.0, 1e-3);  // 2e-12 on 0.5 m: rounding of the planted shift
  EXPECT_NEAR(e.conditioning_out, 3e6, 1.0);
  u[0].reset();
  const ReferenceEstimate f = estimate_reference(u, "non-finite state at step 9", 1.0, 1e-4, s);
  EXPECT_EQ(f.failure, "non-finite state at step 9");
  EXPECT_TRUE(std::isnan(f.error));
  EXPECT_TRUE(std::isnan(f.order));
}

TEST(TradeoffPoints, PlantedResultsBecomePointsAndAFront) {
  // Two engines, two steps, one size; the reference at the origin.
  const CaseLayout l = case_layout({{4, 2}}, 2);
  std::vector<TradeoffEngine> engines(2);
  engines[0].name = "a";
  engines[0].evaluations_per_step = 1;
  engines[1].name = "b";
  Settings s;
  s.seconds = 2.0;
  s.max_error = 0.5;
  std::vector<io::Json> results(l.cases, io::Json::object());
  auto point = [&](double z, double seconds) {
    return io::Json{{"x", vec3s_json(shifted(z))}, {"reason", ""}, {"seconds", num(seconds)}, {"rerun_diff", num(0.0)}};
  };
  results[l.point_case(0, 0, 0)] = point(0.25, 1.0);  // cost 0.5, error 0.25: front
  results[l.point_case(0, 0, 1)] = point(0.1, 2.0);   // cost 1, error 0.1: front
  results[l.point_case(0, 1, 0)] = point(0.3, 4.0);   // cost 2, error 0.3: dominated
  results[l.point_case(0, 1, 1)] = io::Json{{"skipped", true}};
  const std::vector<double> hs = {0.5, 0.25};
  std::vector<Point> pts = size_points(l, 0, hs, engines, results, shifted(0), s);
  ASSERT_EQ(pts.size(), 3u);  // the skipped one is left out
  EXPECT_DOUBLE_EQ(pts[0].cost, 0.5);
  EXPECT_DOUBLE_EQ(pts[0].evals, 2.0);
  EXPECT_TRUE(std::isnan(pts[2].evals));
  EXPECT_NEAR(pts[1].error, 0.1, 1e-15);
  EXPECT_EQ(front_of(pts), (std::vector<int>{0, 1}));
  // A failed run, an error above max_error and a case that threw are not counted, with a status.
  results[l.point_case(0, 0, 0)] = io::Json{{"x", nullptr}, {"reason", "non-finite state at step 3"}, {"seconds", 1.0},
                                            {"rerun_diff", "inf"}};
  results[l.point_case(0, 0, 1)] = point(0.75, 1.0);
  results[l.point_case(0, 1, 0)] = io::Json{{"error", "case 7 threw: planted"}};
  pts = size_points(l, 0, hs, engines, results, shifted(0), s);
  EXPECT_EQ(pts[0].status, "unstable (non-finite state at step 3)");
  EXPECT_EQ(pts[1].status, "unstable (error > 0.5 m)");
  EXPECT_EQ(pts[2].status, "case 7 threw: planted");
  EXPECT_TRUE(front_of(pts).empty());
  EXPECT_EQ(h_label(0.125), "2^-3");
  EXPECT_EQ(h_label(0.3), "0.3");
}

}  // namespace
}  // namespace tecido::suites::tradeoff
