#pragma once
/// What the ensemble of one (response, hold) shows about recovery after the grips let go:
///  - the share of runs that recovered, with Wilson's 95% score interval;
///  - the median recovery time with censoring at the horizon: every censored run is censored at
///    the same time C, after every observed recovery, so the Kaplan-Meier estimate is the
///    empirical distribution below C and its median is the smallest time at which at least half
///    the runs have recovered ("not reached" when fewer than half did); 95% percentile bootstrap
///    interval (resamples of the runs, a deterministic generator per cell), whose ends may be
///    "not reached";
///  - the restricted mean recovery time (each run's time, censored runs counted as C), with its
///    t interval: the per-run value the claims compare (claims.h).
/// Unstable runs are left out of every statistic and counted.
#include "comparisons/suites/forced_contact/run.h"
#include "comparisons/suites/self_contact/statistics.h"

#include <cstdint>
#include <vector>

namespace tecido::suites::forced_contact {

using self_contact::Interval;
using self_contact::Summary;

/// A run's restricted recovery time: its recovery, or C when it did not recover; NaN when unstable.
double restricted_time(const RunResult& r, double censor);

/// The median of times where +inf stands for a censored run: the smallest value with at least
/// half the values at or below it (+inf when that is a censored run).
double censored_median(std::vector<double> times);

/// Percentile bootstrap 95% interval of censored_median (`resamples` resamples, generator `seed`).
Interval bootstrap_median_ci(const std::vector<double>& times, int resamples, std::uint64_t seed);

struct CellOutcome {
  int runs = 0, unstable = 0, recovered = 0;
  int forced = 0;               ///< runs with an intersecting pair at the last held frame
  double held_pairs = 0.0;      ///< mean pairs at the last held frame
  Interval share_ci{0.0, 0.0};  ///< Wilson 95% of recovered / (runs - unstable)
  double median = 0.0;          ///< [s] censored median recovery (+inf: not reached)
  Interval median_ci{0.0, 0.0};
  Summary restricted;           ///< restricted mean recovery time
  int free_at_end = 0;
  std::vector<double> mean_series;  ///< mean pairs per sample over the stable runs
};
CellOutcome cell_outcome(const std::vector<const RunResult*>& runs, const Settings& s, std::uint64_t seed);

}  // namespace tecido::suites::forced_contact
