#pragma once
/// Everything the `tradeoff` suite measured on one cloth size, and the look-ups its report and
/// findings make in it.
#include "comparisons/suites/tradeoff/engines.h"
#include "comparisons/suites/tradeoff/points.h"
#include "comparisons/suites/tradeoff/reference_solution.h"

#include <string>
#include <vector>

namespace tecido::suites::tradeoff {

struct SizeAnalysis {
  int n = 0;
  std::size_t springs = 0;
  double omega = 0.0;         ///< omega_bound [1/s]
  std::vector<double> swept;  ///< h0, h0/2, ... [s]
  ReferenceEstimate reference;
  std::vector<Point> points;
  std::vector<int> front;     ///< indices into points
};

/// The point of engine `name` at swept step j, or nullptr when it was not run.
const Point* point_at(const SizeAnalysis& a, const std::vector<TradeoffEngine>& engines, const std::string& name,
                      std::size_t j);

/// Whether `p` (a point of `a`) is on a's front.
bool on_front(const SizeAnalysis& a, const Point* p);

/// The largest RMS distance between engine `a`'s and engine `b`'s final positions over the steps at
/// which both returned positions on this size [m] (NaN when they share none).
double engines_distance(const SizeAnalysis& size, const std::vector<TradeoffEngine>& engines, const std::string& a,
                        const std::string& b);

}  // namespace tecido::suites::tradeoff
