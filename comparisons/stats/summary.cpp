#include "comparisons/stats/summary.h"

#include "comparisons/stats/distributions.h"

#include <cmath>

namespace tecido::stats {

Summary summarize(const std::vector<double>& xs) {
  Summary s;
  s.n = xs.size();
  if (s.n == 0) {
    s.mean = s.sd = s.se = kNaN;
    s.ci95 = s.pi95 = kNoInterval;
    return s;
  }
  double sum = 0.0;
  bool constant = true;
  for (double x : xs) sum += x, constant = constant && x == xs.front();
  s.mean = constant ? xs.front() : sum / static_cast<double>(s.n);  // equal values: exactly that value, sd 0
  if (s.n < 2) {
    s.sd = s.se = kNaN;
    s.ci95 = s.pi95 = kNoInterval;
    return s;
  }
  double ss = 0.0;
  if (!constant)
    for (double x : xs) ss += (x - s.mean) * (x - s.mean);
  const double n = static_cast<double>(s.n);
  s.sd = std::sqrt(ss / (n - 1.0));
  s.se = s.sd / std::sqrt(n);
  const double t = student_t_quantile(0.975, n - 1.0);
  s.ci95 = {s.mean - t * s.se, s.mean + t * s.se};
  const double w = t * s.sd * std::sqrt(1.0 + 1.0 / n);
  s.pi95 = {s.mean - w, s.mean + w};
  return s;
}

}  // namespace tecido::stats
