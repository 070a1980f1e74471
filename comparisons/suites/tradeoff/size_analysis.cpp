#include "comparisons/suites/tradeoff/size_analysis.h"

#include "comparisons/suites/tradeoff/distances.h"

#include <algorithm>
#include <cmath>

namespace tecido::suites::tradeoff {

const Point* point_at(const SizeAnalysis& a, const std::vector<TradeoffEngine>& engines, const std::string& name,
                      std::size_t j) {
  for (const Point& p : a.points)
    if (engines[p.engine].name == name && p.step == j) return &p;
  return nullptr;
}

bool on_front(const SizeAnalysis& a, const Point* p) {
  if (!p) return false;
  const int i = static_cast<int>(p - a.points.data());
  return std::find(a.front.begin(), a.front.end(), i) != a.front.end();
}

double engines_distance(const SizeAnalysis& size, const std::vector<TradeoffEngine>& engines, const std::string& a,
                        const std::string& b) {
  double worst = NAN;
  for (std::size_t j = 0; j < size.swept.size(); ++j) {
    const Point *pa = point_at(size, engines, a, j), *pb = point_at(size, engines, b, j);
    if (!pa || !pb || pa->x.empty() || pb->x.empty()) continue;
    const double d = rms_distance(pa->x, pb->x);
    worst = std::isnan(worst) ? d : std::max(worst, d);
  }
  return worst;
}

}  // namespace tecido::suites::tradeoff
