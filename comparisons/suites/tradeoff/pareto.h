#pragma once
/// The Pareto front of points in the cost/error plane (lower is better in both).
#include <vector>

namespace tecido::suites::tradeoff {

/// One point of the cost/error plane.
struct CostError {
  double cost = 0.0;
  double error = 0.0;
};

/// Indices of the Pareto front of `pts`: the points that no other point dominates (dominates = no
/// worse in both, strictly better in at least one). Points with a non-finite coordinate are
/// neither on the front nor dominate. Equal points are all kept. Sorted by increasing cost, ties by
/// increasing error, then by index. By transitivity every finite point off the front is dominated
/// by a point on it, so "on the front or dominated" holds by construction and is not checked.
std::vector<int> pareto_front(const std::vector<CostError>& pts);

}  // namespace tecido::suites::tradeoff
