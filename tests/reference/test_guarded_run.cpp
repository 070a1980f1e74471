// The one guarded fixed-time runner (reference/guarded_run.h), on planted engines: a particle
// moving at a known speed (so where it is after n steps, and when it passes the stray limit, is
// hand-worked), and one whose state turns non-finite at a chosen step.
#include "reference/guarded_run.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace tecido::reference {
namespace {

// One particle from the origin along x at `speed` m per step; step `nan_at` (1-based, 0 = never)
// reports a non-finite state.
class Planted final {
 public:
  Planted(double speed, long long nan_at) : speed_(speed), nan_at_(nan_at) {}
  bool step() {
    ++steps_;
    if (steps_ == nan_at_) x_ = std::numeric_limits<double>::quiet_NaN();
    else x_ += speed_;
    return std::isfinite(x_);
  }
  std::vector<Vec3> positions() const { return {Vec3(x_, 0, 0)}; }
  std::vector<Vec3> velocities() const { return {Vec3(speed_, 0, 0)}; }
  std::vector<std::string> not_modelled() const { return {}; }
  double time() const { return static_cast<double>(steps_); }
  long long steps_done() const { return steps_; }

 private:
  double speed_;
  long long nan_at_;
  long long steps_ = 0;
  double x_ = 0.0;
};

const std::vector<Vec3> kStart = {Vec3::Zero()};

TEST(GuardedRun, ACleanRunReturnsThePositionsAfterExactlyTheSteps) {
  Planted e(0.5, 0);
  const GuardedRun r = run_guarded(e, kStart, 100, 1e3);
  ASSERT_TRUE(r.x.has_value());
  EXPECT_EQ((*r.x)[0], Vec3(50.0, 0, 0));
  EXPECT_EQ(e.steps_done(), 100);
  EXPECT_EQ(r.failed_at_step, 0);
  EXPECT_TRUE(r.reason.empty());
}

TEST(GuardedRun, ANonFiniteStepEndsTheRunThere) {
  Planted e(0.5, 37);
  const GuardedRun r = run_guarded(e, kStart, 100, 1e3);
  EXPECT_FALSE(r.x.has_value());
  EXPECT_EQ(r.failed_at_step, 37);
  EXPECT_EQ(r.reason, "non-finite state at step 37");
  EXPECT_EQ(e.steps_done(), 37);  // not one step more
}

TEST(GuardedRun, AStrayNodeIsSeenAtTheNextCheck) {
  // 10 m per step passes 1000 m at step 101; checks come every 64 steps: the one at step 128 sees it.
  Planted e(10.0, 0);
  const GuardedRun r = run_guarded(e, kStart, 1000, 1000.0);
  EXPECT_FALSE(r.x.has_value());
  EXPECT_EQ(r.failed_at_step, 128);
  EXPECT_EQ(r.reason, "a node more than 1000 m from its start at step 128");
  // A shorter run that strays between checks is caught after its last step.
  Planted f(10.0, 0);
  const GuardedRun s = run_guarded(f, kStart, 120, 1000.0);
  EXPECT_FALSE(s.x.has_value());
  EXPECT_EQ(s.failed_at_step, 120);
  // Exactly at the limit is not astray.
  Planted g(10.0, 0);
  EXPECT_TRUE(run_guarded(g, kStart, 100, 1000.0).x.has_value());
}

TEST(GuardedRun, FixedTimeStepsRound) {
  EXPECT_EQ(fixed_time_steps(1.0, 1.0 / 240.0), 240);
  EXPECT_EQ(fixed_time_steps(1.0, 0.3), 3);
  EXPECT_EQ(fixed_time_steps(0.0, 0.1), 0);
}

}  // namespace
}  // namespace tecido::reference
