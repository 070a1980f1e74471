#pragma once
/// Correlation of paired samples: Pearson's r, Spearman's rank correlation (Pearson's r of the
/// mid-ranks, so ties share their average rank) and an approximate 95% interval for Spearman's
/// by Fisher's z with the variance 1.06 / (n - 3) of Fieller, Hartley and Pearson (1957,
/// Biometrika 44:470-481): tanh(atanh(r_s) +- z_0.975 sqrt(1.06 / (n - 3))).
#include "comparisons/stats/summary.h"

#include <vector>

namespace tecido::stats {

/// Pearson's correlation; NaN for fewer than 2 pairs or no spread in either sample.
double pearson(const std::vector<double>& a, const std::vector<double>& b);
/// Ranks 1..n, ties given the mean of the ranks they span.
std::vector<double> mid_ranks(const std::vector<double>& xs);

struct Correlation {
  double r = kNaN;
  Interval ci95 = kNoInterval;  ///< NaN for n < 4 or r undefined
  std::size_t n = 0;
};
Correlation spearman(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace tecido::stats
