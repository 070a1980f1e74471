#include "comparisons/suites/stability/theory.h"

#include <cmath>
#include <limits>

namespace tecido::suites::stability {

double amplification(IntegratorKind k, double c) {
  switch (k) {
    case IntegratorKind::Euler: return std::sqrt(1.0 + c * c);
    case IntegratorKind::Midpoint: return std::sqrt(1.0 + c * c * c * c / 4.0);
    case IntegratorKind::RK4: {
      const double re = 1.0 - c * c / 2.0 + c * c * c * c / 24.0, im = c - c * c * c / 6.0;
      return std::sqrt(re * re + im * im);
    }
    case IntegratorKind::Symplectic: {
      if (c <= 2.0) return 1.0;
      const double b = c * c - 2.0;
      return 0.5 * (b + std::sqrt(b * b - 4.0));
    }
  }
  return std::nan("");
}

double stable_limit(IntegratorKind k) {
  switch (k) {
    case IntegratorKind::Symplectic: return 2.0;
    case IntegratorKind::RK4: return 2.0 * std::sqrt(2.0);
    default: return std::nan("");
  }
}

double growth_per_period(IntegratorKind k, double c) { return std::pow(amplification(k, c), 2.0 * kPi / c); }

double horizon_prediction(IntegratorKind k, double periods, double bound) {
  double lo = 1e-9, hi = 1.999;
  auto f = [&](double c) { return 2.0 * kPi * periods / c * std::log(amplification(k, c)) - std::log(bound); };
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

double bound_stretch_limit(double bound) { return 2.0 * std::sqrt(1.0 - 1.0 / (bound * bound)); }

double pair_omega_max(double ks, double m1, double m2) { return std::sqrt(ks * (1.0 / m1 + 1.0 / m2)); }

double chain_omega_max(double ks, double m1, double m2) {
  const double T = 2.0 * ks / m1 + ks / m2, D = ks * ks / (m1 * m2);
  return std::sqrt(0.5 * (T + std::sqrt(T * T - 4.0 * D)));
}

double ulp_of(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()) - x; }

double underflow_separation() {
  // denorm_min / 2 itself rounds to 0, so halve after the root.
  return std::sqrt(std::numeric_limits<double>::denorm_min()) / std::sqrt(2.0);
}

}  // namespace tecido::suites::stability
