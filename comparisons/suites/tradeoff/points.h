#pragma once
/// One cloth size's measured points on the cost/error plane, from its case results, and its
/// Pareto front.
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/tradeoff/cases.h"
#include "comparisons/suites/tradeoff/engines.h"

#include <optional>
#include <string>
#include <vector>

namespace tecido::suites::tradeoff {

struct Point {
  std::size_t engine = 0;  ///< index into the engines
  std::size_t step = 0;    ///< index into the swept steps
  double h = 0.0;          ///< [s]
  bool counted = false;    ///< finite, and its error is at most Settings::max_error
  std::string status;      ///< "counted", or why not
  double cost = NAN;       ///< wall seconds per simulated second
  double evals = NAN;      ///< force evaluations per simulated second (NaN: not counted for the engine)
  double error = NAN;      ///< RMS distance to the reference at T [m]
  double rerun_diff = INFINITY;  ///< max |x - x_rerun| [m]
  std::vector<Vec3> x;     ///< final positions (empty when the run failed)
};

/// The points of size si (skipped ones left out), engine-major, each measured against `ref` (the
/// reference's positions; nothing when it failed, which leaves every error NaN and no point counted).
/// A case that threw becomes a point whose status is its error.
std::vector<Point> size_points(const CaseLayout& layout, std::size_t si, const std::vector<double>& swept,
                               const std::vector<TradeoffEngine>& engines, const std::vector<io::Json>& results,
                               const std::optional<std::vector<Vec3>>& ref, const Settings& s);

/// Indices into `points` of the Pareto front of the counted points (pareto.h), by increasing cost.
std::vector<int> front_of(const std::vector<Point>& points);

/// "2^-7" for a power of two, else 3 significant digits.
std::string h_label(double h);

}  // namespace tecido::suites::tradeoff
