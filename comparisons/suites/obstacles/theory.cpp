#include "comparisons/suites/obstacles/theory.h"

#include <cmath>
#include <limits>

namespace tecido::suites::obstacles {

double fall_time(double height, double g) { return std::sqrt(2.0 * height / g); }

double rebound_apex(double height, double k) { return k * k * height; }

double slide_distance(double a, double mu, double h, long long n) {
  const double nd = static_cast<double>(n);
  if (mu == 0.0) return a * h * h * nd * (nd + 1.0) / 2.0;
  const double q = 1.0 - mu;
  return a * h * h / mu * (nd - q * (1.0 - std::pow(q, nd)) / mu);
}

double slide_terminal_speed(double a, double mu, double h) {
  return mu == 0.0 ? std::numeric_limits<double>::infinity() : a * h / mu;
}

}  // namespace tecido::suites::obstacles
