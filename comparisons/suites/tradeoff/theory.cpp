#include "comparisons/suites/tradeoff/theory.h"

#include <algorithm>
#include <cmath>

namespace tecido::suites::tradeoff {

double omega_bound(const Scene& scene) {
  std::vector<double> k(scene.particles.size(), 0.0);
  for (const Spring& sp : scene.forces.springs) {
    k[sp.i] += 2.0 * sp.stiffness;
    k[sp.j] += 2.0 * sp.stiffness;
  }
  double w2 = 0.0;
  for (std::size_t i = 0; i < k.size(); ++i) w2 = std::max(w2, k[i] * scene.particles.inv_mass[i]);
  return std::sqrt(w2);
}

double first_step(const Scene& scene) { return std::pow(2.0, std::ceil(std::log2(2.0 / omega_bound(scene)))); }

std::vector<double> swept_steps(const Scene& scene, int count) {
  const double h0 = first_step(scene);
  std::vector<double> hs;
  for (int j = 0; j < count; ++j) hs.push_back(h0 / std::pow(2.0, j));
  return hs;
}

double richardson_error(double diff, double order) { return diff / (std::pow(2.0, order) - 1.0); }

double observed_order(double error_h, double error_half_h) { return std::log2(error_h / error_half_h); }

}  // namespace tecido::suites::tradeoff
