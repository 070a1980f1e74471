#pragma once
/// The statistics of the self-contact experiment: the shared ones (comparisons/stats/: summaries,
/// Student t, binomial tails, Wilson, correlation) under this namespace's names, and the few
/// helpers only this experiment uses.
#include "comparisons/stats/stats.h"

#include <cstddef>
#include <vector>

namespace tecido::suites::self_contact {

using stats::binomial_upper_tail;
using stats::incomplete_beta;
using stats::Interval;
using stats::kNaN;
using stats::log_gamma;
using stats::pearson;
using stats::student_t_cdf;
using stats::student_t_quantile;
using stats::summarize;
using stats::Summary;

/// Welch's 95% interval of mean(a) - mean(b) from two summaries (standard errors se_a, se_b,
/// sample sizes n_a, n_b >= 2), df by Welch-Satterthwaite. NaN when it cannot be computed.
Interval welch_ci95(double mean_a, double se_a, std::size_t n_a, double mean_b, double se_b, std::size_t n_b);

/// One-sided sign test: P(X >= k) for X ~ Binomial(n, 1/2).
double sign_test_p(int k, int n);

/// Wilson's 95% score interval of a proportion k / n (n >= 1).
Interval wilson_ci95(int k, int n);

/// Where x falls in the sample: (#{x_i < x} + #{x_i == x} / 2) / n (the mid-rank percentile);
/// NaN for an empty sample.
double mid_percentile(const std::vector<double>& xs, double x);

}  // namespace tecido::suites::self_contact
