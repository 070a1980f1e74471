#include "comparisons/stats/rank_correlation.h"

#include "comparisons/stats/distributions.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace tecido::stats {

double pearson(const std::vector<double>& a, const std::vector<double>& b) {
  const std::size_t n = a.size();
  if (n < 2 || b.size() != n) return kNaN;
  double ma = 0.0, mb = 0.0;
  for (std::size_t i = 0; i < n; ++i) ma += a[i], mb += b[i];
  ma /= static_cast<double>(n);
  mb /= static_cast<double>(n);
  double sab = 0.0, saa = 0.0, sbb = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  if (!(saa > 0.0 && sbb > 0.0)) return kNaN;
  return sab / std::sqrt(saa * sbb);
}

std::vector<double> mid_ranks(const std::vector<double>& xs) {
  std::vector<std::size_t> order(xs.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return xs[a] < xs[b]; });
  std::vector<double> rank(xs.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && xs[order[j + 1]] == xs[order[i]]) ++j;
    const double mean_rank = 0.5 * static_cast<double>(i + j) + 1.0;  // ranks i+1 .. j+1
    for (std::size_t k = i; k <= j; ++k) rank[order[k]] = mean_rank;
    i = j + 1;
  }
  return rank;
}

Correlation spearman(const std::vector<double>& a, const std::vector<double>& b) {
  Correlation c;
  c.n = a.size();
  if (b.size() != a.size()) return c;
  c.r = pearson(mid_ranks(a), mid_ranks(b));
  if (c.n < 4 || std::isnan(c.r)) return c;
  const double z = std::atanh(c.r), half = normal_quantile(0.975) * std::sqrt(1.06 / (static_cast<double>(c.n) - 3.0));
  c.ci95 = {std::tanh(z - half), std::tanh(z + half)};
  return c;
}

}  // namespace tecido::stats
