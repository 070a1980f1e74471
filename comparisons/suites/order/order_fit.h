#pragma once
/// The observed order of convergence of a sequence of errors at halving steps, fitted over the
/// range where it follows a power law (the asymptotic range), which the fit finds itself.
#include <cmath>
#include <vector>

namespace tecido::suites {

/// Where a sequence of (h, error) pairs follows a power law.
struct OrderFit {
  std::vector<double> observed;  ///< log2(e_k / e_{k+1}) per halving (NaN where undefined)
  int first = -1, last = -1;     ///< step-size indices of the asymptotic range (inclusive), -1 if none
  double slope = std::nan("");   ///< least-squares slope of log e against log h over the range
  double roundoff_below_h = 0.0; ///< smallest h whose error is above the round-off floor (0 if none excluded)
  double unstable_above_h = 0.0; ///< largest h excluded as unstable/pre-asymptotic (0 if none)
};

/// Finds the asymptotic range in errors `e` at steps `h` (h halving each index): errors must be
/// finite, below `too_big` (instability or pre-asymptotic) and above `floor` (round-off); the
/// range is the longest run of consecutive halvings whose observed orders differ by at most
/// `agree` from one halving to the next, at least `min_halvings` long. The slope is NaN when no
/// such range exists.
OrderFit fit_order(const std::vector<double>& h, const std::vector<double>& e, double floor, double too_big,
                   double agree = 0.1, int min_halvings = 3);

}  // namespace tecido::suites
