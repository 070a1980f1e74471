#include "comparisons/suites/forced_contact/recovery.h"

#include "comparisons/suites/random.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tecido::suites::forced_contact {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// The value at quantile q of sorted xs (the lower order statistic at ceil(q n) - 1).
double order_statistic(const std::vector<double>& sorted, double q) {
  const auto n = static_cast<double>(sorted.size());
  const auto k = static_cast<std::size_t>(std::max(0.0, std::ceil(q * n) - 1.0));
  return sorted[std::min(k, sorted.size() - 1)];
}

}  // namespace

double restricted_time(const RunResult& r, double censor) {
  if (r.status != "ok") return self_contact::kNaN;
  return r.recovered ? r.recovery : censor;
}

double censored_median(std::vector<double> times) {
  if (times.empty()) return self_contact::kNaN;
  std::sort(times.begin(), times.end());
  return order_statistic(times, 0.5);
}

Interval bootstrap_median_ci(const std::vector<double>& times, int resamples, std::uint64_t seed) {
  if (times.size() < 2 || resamples < 1) return {self_contact::kNaN, self_contact::kNaN};
  Rng rng(seed);
  std::vector<double> medians, draw(times.size());
  for (int b = 0; b < resamples; ++b) {
    for (double& x : draw) x = times[rng.below(times.size())];
    medians.push_back(censored_median(draw));
  }
  std::sort(medians.begin(), medians.end());
  return {order_statistic(medians, 0.025), order_statistic(medians, 0.975)};
}

CellOutcome cell_outcome(const std::vector<const RunResult*>& runs, const Settings& s, std::uint64_t seed) {
  CellOutcome c;
  std::vector<double> times, restricted;
  std::vector<const RunResult*> ok;
  for (const RunResult* r : runs) {
    ++c.runs;
    if (r->status != "ok") {
      ++c.unstable;
      continue;
    }
    ok.push_back(r);
    c.recovered += r->recovered;
    c.forced += r->held_pairs > 0;
    c.free_at_end += r->free_at_end;
    c.held_pairs += static_cast<double>(r->held_pairs);
    times.push_back(r->recovered ? r->recovery : kInf);
    restricted.push_back(restricted_time(*r, censor_time(s)));
  }
  const int n = static_cast<int>(ok.size());
  c.held_pairs = n ? c.held_pairs / n : self_contact::kNaN;
  c.share_ci = self_contact::wilson_ci95(c.recovered, n);
  c.median = censored_median(times);
  c.median_ci = bootstrap_median_ci(times, s.bootstrap, seed);
  c.restricted = self_contact::summarize(restricted);
  std::size_t len = 0;
  for (const RunResult* r : ok) len = std::max(len, r->series.size());
  c.mean_series.assign(len, 0.0);
  for (const RunResult* r : ok)
    for (std::size_t k = 0; k < r->series.size(); ++k) c.mean_series[k] += static_cast<double>(r->series[k]) / n;
  return c;
}

}  // namespace tecido::suites::forced_contact
