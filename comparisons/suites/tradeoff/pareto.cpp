#include "comparisons/suites/tradeoff/pareto.h"

#include <algorithm>
#include <cmath>

namespace tecido::suites::tradeoff {

std::vector<int> pareto_front(const std::vector<CostError>& pts) {
  const int n = static_cast<int>(pts.size());
  auto finite = [&](int i) { return std::isfinite(pts[i].cost) && std::isfinite(pts[i].error); };
  std::vector<int> front;
  for (int i = 0; i < n; ++i) {
    if (!finite(i)) continue;
    bool dominated = false;
    for (int j = 0; j < n && !dominated; ++j) {
      if (j == i || !finite(j)) continue;
      const bool no_worse = pts[j].cost <= pts[i].cost && pts[j].error <= pts[i].error;
      const bool better = pts[j].cost < pts[i].cost || pts[j].error < pts[i].error;
      dominated = no_worse && better;
    }
    if (!dominated) front.push_back(i);
  }
  std::sort(front.begin(), front.end(), [&](int a, int b) {
    if (pts[a].cost != pts[b].cost) return pts[a].cost < pts[b].cost;
    if (pts[a].error != pts[b].error) return pts[a].error < pts[b].error;
    return a < b;
  });
  return front;
}

}  // namespace tecido::suites::tradeoff
