#pragma once
/// One engine on one problem at a sequence of halving steps: the global error at T against the
/// exact solution, and the wall time of each run (the `order` suite's cases).
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/order/order_engines.h"
#include "comparisons/suites/order/problems.h"

#include <string>
#include <vector>

namespace tecido::suites::order {

struct Sample {
  double h = 0.0;
  double error = 0.0;    ///< max over particles of |x(T) - exact(T)| [m]; +inf when the run blew up
  double seconds = 0.0;  ///< wall time of the run (not part of the determinism promise)
};

/// Runs `engine` on `p` for T / h steps; the error is +inf when a step failed.
Sample run_once(const Problem& p, const OrderEngine& engine, double h);

/// Runs at h0, h0/2, ..., h0/2^halvings.
std::vector<Sample> convergence_runs(const Problem& p, const OrderEngine& engine, double h0, int halvings);

/// Samples as JSON (lossless, infinities included) and back.
io::Json samples_json(const std::vector<Sample>& s);
std::vector<Sample> samples_from_json(const io::Json& j);

}  // namespace tecido::suites::order
