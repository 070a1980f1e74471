#include "core/dynamics/integrator.h"

namespace tecido {

const char* integrator_name(IntegratorKind k) {
  switch (k) {
    case IntegratorKind::Euler: return "euler";
    case IntegratorKind::Symplectic: return "symplectic";
    case IntegratorKind::Midpoint: return "midpoint";
    case IntegratorKind::RK4: return "rk4";
  }
  return "?";
}

std::optional<IntegratorKind> parse_integrator(const std::string& name) {
  if (name == "euler") return IntegratorKind::Euler;
  if (name == "symplectic") return IntegratorKind::Symplectic;
  if (name == "midpoint") return IntegratorKind::Midpoint;
  if (name == "rk4") return IntegratorKind::RK4;
  return std::nullopt;
}

int evaluations_per_step(IntegratorKind k) {
  switch (k) {
    case IntegratorKind::Euler:
    case IntegratorKind::Symplectic: return 1;
    case IntegratorKind::Midpoint: return 2;
    case IntegratorKind::RK4: return 4;
  }
  return 1;
}

void Integrator::step(const AccelerationFn& accel, double t, double h, std::vector<Vec3>& x, std::vector<Vec3>& v) {
  const std::size_t n = x.size();
  a1_.resize(n);
  switch (kind_) {
    case IntegratorKind::Euler:
      accel(t, x, v, a1_);
      for (std::size_t i = 0; i < n; ++i) {
        x[i] += h * v[i];
        v[i] += h * a1_[i];
      }
      return;
    case IntegratorKind::Symplectic:
      accel(t, x, v, a1_);
      for (std::size_t i = 0; i < n; ++i) {
        v[i] += h * a1_[i];
        x[i] += h * v[i];
      }
      return;
    case IntegratorKind::Midpoint: {
      accel(t, x, v, a1_);
      xs_.resize(n);
      vs_.resize(n);
      a2_.resize(n);
      const double hh = 0.5 * h;
      for (std::size_t i = 0; i < n; ++i) {
        xs_[i] = x[i] + hh * v[i];
        vs_[i] = v[i] + hh * a1_[i];
      }
      accel(t + hh, xs_, vs_, a2_);
      for (std::size_t i = 0; i < n; ++i) {
        x[i] += h * vs_[i];
        v[i] += h * a2_[i];
      }
      return;
    }
    case IntegratorKind::RK4: {
      xs_.resize(n);
      a2_.resize(n);
      a3_.resize(n);
      a4_.resize(n);
      v2_.resize(n);
      v3_.resize(n);
      v4_.resize(n);
      const double hh = 0.5 * h;
      accel(t, x, v, a1_);
      for (std::size_t i = 0; i < n; ++i) {
        xs_[i] = x[i] + hh * v[i];
        v2_[i] = v[i] + hh * a1_[i];
      }
      accel(t + hh, xs_, v2_, a2_);
      for (std::size_t i = 0; i < n; ++i) {
        xs_[i] = x[i] + hh * v2_[i];
        v3_[i] = v[i] + hh * a2_[i];
      }
      accel(t + hh, xs_, v3_, a3_);
      for (std::size_t i = 0; i < n; ++i) {
        xs_[i] = x[i] + h * v3_[i];
        v4_[i] = v[i] + h * a3_[i];
      }
      accel(t + h, xs_, v4_, a4_);
      const double h6 = h / 6.0;
      for (std::size_t i = 0; i < n; ++i) {
        x[i] += h6 * (v[i] + 2.0 * v2_[i] + 2.0 * v3_[i] + v4_[i]);
        v[i] += h6 * (a1_[i] + 2.0 * a2_[i] + 2.0 * a3_[i] + a4_[i]);
      }
      return;
    }
  }
}

}  // namespace tecido
