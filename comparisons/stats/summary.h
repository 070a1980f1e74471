#pragma once
/// A sample summarised: mean, sample standard deviation, the 95% Student t interval of the mean
/// and the 95% prediction interval of one more draw. The interval type every test here returns.
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace tecido::stats {

/// A value that is not there (no runs, no interval): NaN.
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// An interval [lo, hi]; NaN ends when it cannot be computed.
struct Interval {
  double lo = 0.0, hi = 0.0;
  bool contains(double x) const { return lo <= x && x <= hi; }
  bool below(double x) const { return hi < x; }  ///< every point < x
  bool above(double x) const { return lo > x; }  ///< every point > x
  bool defined() const { return !std::isnan(lo) && !std::isnan(hi); }
};
inline constexpr Interval kNoInterval{kNaN, kNaN};

/// Mean, sample standard deviation (n - 1), the 95% t interval of the mean and the 95%
/// prediction interval of one more draw (mean +- t sd sqrt(1 + 1/n)); n < 2 gives NaN spreads.
struct Summary {
  std::size_t n = 0;
  double mean = 0.0, sd = 0.0, se = 0.0;
  Interval ci95, pi95;
  /// n >= 2 values, all equal: an interval of width 0 that says nothing about a population.
  bool without_variation() const { return n >= 2 && sd == 0.0; }
};
Summary summarize(const std::vector<double>& xs);

}  // namespace tecido::stats
