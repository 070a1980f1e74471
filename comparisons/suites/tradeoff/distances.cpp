#include "comparisons/suites/tradeoff/distances.h"

#include <cmath>
#include <limits>

namespace tecido::suites::tradeoff {

double rms_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  if (a.empty() || a.size() != b.size()) return std::nan("");
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]).squaredNorm();
  return std::sqrt(s / static_cast<double>(a.size()));
}

double max_abs_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  if (a.size() != b.size()) return std::numeric_limits<double>::infinity();
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double d = (a[i] - b[i]).cwiseAbs().maxCoeff();
    if (!(d <= m)) m = std::isnan(d) ? std::numeric_limits<double>::infinity() : d;
  }
  return m;
}

}  // namespace tecido::suites::tradeoff
