#include "comparisons/suites/drift/theory.h"

#include "core/dynamics/force_model.h"

#include <cmath>
#include <stdexcept>

namespace tecido::suites::drift {

std::optional<Tableau> runge_kutta_tableau(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::Euler: return Tableau{{{0.0}}, {1.0}};
    case IntegratorKind::Midpoint: return Tableau{{{0.0, 0.0}, {0.5, 0.0}}, {0.0, 1.0}};
    case IntegratorKind::RK4:
      return Tableau{{{0, 0, 0, 0}, {0.5, 0, 0, 0}, {0, 0.5, 0, 0}, {0, 0, 1.0, 0}},
                     {1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0}};
    case IntegratorKind::Symplectic: return std::nullopt;
  }
  return std::nullopt;
}

bool conserves_angular_momentum(IntegratorKind kind) { return kind == IntegratorKind::Symplectic; }

Vec3 angular_momentum_change(const Tableau& t, const std::vector<Spring>& springs, const std::vector<double>& inv_mass,
                             const std::vector<Vec3>& x, const std::vector<Vec3>& v, double h) {
  const std::size_t s = t.b.size(), n = x.size();
  for (double w : inv_mass)
    if (!(w > 0.0)) throw std::invalid_argument("angular_momentum_change: every particle must be free");
  std::vector<std::vector<Vec3>> V(s), F(s);
  std::vector<Vec3> X(n);
  for (std::size_t i = 0; i < s; ++i) {
    V[i] = v;
    X = x;
    for (std::size_t j = 0; j < i; ++j) {
      if (t.a[i][j] == 0.0) continue;
      for (std::size_t k = 0; k < n; ++k) {
        X[k] += h * t.a[i][j] * V[j][k];
        V[i][k] += h * t.a[i][j] * inv_mass[k] * F[j][k];
      }
    }
    accumulate_spring_forces(springs, X, V[i], F[i]);  // central forces, damping included
  }
  Vec3 dl = Vec3::Zero();
  for (std::size_t i = 0; i < s; ++i) {
    for (std::size_t j = 0; j < s; ++j) {
      const double m = t.b[i] * t.b[j] - t.b[i] * t.a[i][j] - t.b[j] * t.a[j][i];
      if (m == 0.0) continue;
      Vec3 sum = Vec3::Zero();
      for (std::size_t k = 0; k < n; ++k) sum += V[i][k].cross(F[j][k]);
      dl += m * sum;
    }
  }
  return h * h * dl;
}

double fall_time(double z0, double g) { return std::sqrt(2.0 * z0 / g); }

double classic_sag_ratio(double load_factor) { return 1.0 / load_factor; }

}  // namespace tecido::suites::drift
