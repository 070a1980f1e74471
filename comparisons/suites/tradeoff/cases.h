#pragma once
/// The `tradeoff` suite's cases: which case index is which run, and the two case groups.
///
/// Case order: for each cloth size, its kUntimed untimed runs (reference_solution.h), then one
/// timed point per engine (outer) and swept step (inner). A point outside an engine's range
/// (TradeoffEngine::max_n, max_steps) is a case too, whose result says it was skipped, so the
/// indices depend on the sizes and the engine count only.
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/tradeoff/engines.h"
#include "comparisons/suites/tradeoff/reference_solution.h"
#include "comparisons/suites/tradeoff/settings.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace tecido::suites::tradeoff {

/// What case k is.
struct CaseIndex {
  std::size_t size = 0;                  ///< index into the sizes
  bool timed = false;                    ///< a point (engine, step) or an untimed run
  Untimed untimed = Untimed::Reference;  ///< when !timed
  std::size_t engine = 0, step = 0;      ///< when timed
};

/// Where each size's cases start.
struct CaseLayout {
  std::vector<Size> sizes;
  std::size_t engines = 0;
  std::vector<std::size_t> first;  ///< per size
  std::size_t cases = 0;

  CaseIndex locate(std::size_t k) const;
  /// The case index of size si's untimed run `u`, or of its point (engine e, step j).
  std::size_t untimed_case(std::size_t si, Untimed u) const { return first[si] + static_cast<std::size_t>(u); }
  std::size_t point_case(std::size_t si, std::size_t e, std::size_t j) const {
    return first[si] + kUntimed + e * static_cast<std::size_t>(sizes[si].steps) + j;
  }
};

CaseLayout case_layout(const std::vector<Size>& sizes, std::size_t engines);

/// A run's result as JSON: {"x": positions or null, "reason": why it failed ("" when it did not)}.
io::Json run_json(const reference::GuardedRun& r);
/// The positions of run_json's result (nothing when the run failed).
std::optional<std::vector<Vec3>> positions_of(const io::Json& result);

/// Case group 1, an untimed run: run_json of untimed_run.
io::Json untimed_case(Untimed which, const Scene& scene, const std::vector<double>& swept, const Settings& s,
                      std::uint64_t seed, int n);

/// A timed run: the untimed first call (it fills any per-engine cache, such as the classic soft
/// body's kLST calibration, which is set-up, not stepping), then timed calls: a run shorter than
/// s.timing_min_seconds is repeated (up to s.timing_max_repeats calls or s.timing_max_total
/// seconds) and the fastest call is kept. rerun_diff: the first timed call's positions against
/// the untimed call's (max |x - x_rerun|; +inf when the run failed).
struct Timed {
  reference::GuardedRun run;
  double seconds = 0.0;
  int repeats = 0;
  double rerun_diff = INFINITY;
};
Timed timed_run(const TradeoffEngine& e, const Scene& scene, double h, const Settings& s);

/// Case group 2, a timed point: {"skipped": true} outside the engine's range, else run_json plus
/// "seconds" (wall seconds of one run on this machine) and "rerun_diff".
io::Json point_case(const TradeoffEngine& e, const Scene& scene, int n, std::size_t j, double h, const Settings& s);

}  // namespace tecido::suites::tradeoff
