#pragma once
/// Every obstacle's pose at the two ends of the interval the contact loop is looking at: the
/// start of the current sub-step (fixed while it is bisected) and a trial end (each bisection
/// moves it). Recomputed only when the time changes.
#include "core/geometry/obstacle_pose.h"

#include <cmath>
#include <limits>
#include <vector>

namespace tecido {

class ObstaclePoses {
 public:
  explicit ObstaclePoses(const std::vector<Obstacle>& obstacles)
      : obstacles_(&obstacles), start_(obstacles.size()), end_(obstacles.size()) {}

  /// Poses at the start of the interval.
  void at_start(double t) { set(start_, start_time_, t); }
  /// Poses at the interval's (trial) end.
  void at_end(double t) { set(end_, end_time_, t); }
  const ObstaclePose& start(std::size_t k) const { return start_[k]; }
  const ObstaclePose& end(std::size_t k) const { return end_[k]; }
  std::size_t size() const { return start_.size(); }

 private:
  void set(std::vector<ObstaclePose>& poses, double& cached, double t) {
    if (t == cached) return;
    const bool first = std::isnan(cached);
    for (std::size_t k = 0; k < poses.size(); ++k)
      if (first || (*obstacles_)[k].moving()) obstacle_pose_at((*obstacles_)[k], t, poses[k]);
    cached = t;
  }
  const std::vector<Obstacle>* obstacles_;
  std::vector<ObstaclePose> start_, end_;
  double start_time_ = std::numeric_limits<double>::quiet_NaN();  // NaN: no pose yet
  double end_time_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace tecido
