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

namespace {

// The state arrays as flat doubles (3 per particle), so the update loops below are plain
// stride-1 loops the compiler vectorizes. Each performs, component by component, exactly the
// operations of the Vec3 expression in its comment.
double* flat(std::vector<Vec3>& a) { return a.empty() ? nullptr : a.front().data(); }

// y += h * x
void add_scaled(double* __restrict y, double h, const double* __restrict x, std::size_t m) {
  for (std::size_t k = 0; k < m; ++k) y[k] += h * x[k];
}
// y = x + h * z
void set_sum_scaled(double* __restrict y, const double* __restrict x, double h, const double* __restrict z,
                    std::size_t m) {
  for (std::size_t k = 0; k < m; ++k) y[k] = x[k] + h * z[k];
}
// y += h6 * (((a + 2 b) + 2 c) + d): the RK4 combination
void add_rk4(double* __restrict y, double h6, const double* __restrict a, const double* __restrict b,
             const double* __restrict c, const double* __restrict d, std::size_t m) {
  for (std::size_t k = 0; k < m; ++k) y[k] += h6 * (((a[k] + 2.0 * b[k]) + 2.0 * c[k]) + d[k]);
}

}  // namespace

void Integrator::step(const AccelerationFn& accel, double t, double h, std::vector<Vec3>& x, std::vector<Vec3>& v) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 arrays are updated as packed doubles");
  const std::size_t n = x.size();
  const std::size_t m = 3 * n;
  a1_.resize(n);
  switch (kind_) {
    case IntegratorKind::Euler:
      accel(t, x, v, a1_);
      add_scaled(flat(x), h, flat(v), m);    // x += h v(t)
      add_scaled(flat(v), h, flat(a1_), m);  // v += h a(t)
      return;
    case IntegratorKind::Symplectic:
      accel(t, x, v, a1_);
      add_scaled(flat(v), h, flat(a1_), m);  // v += h a(t)
      add_scaled(flat(x), h, flat(v), m);    // x += h v(t + h)
      return;
    case IntegratorKind::Midpoint: {
      accel(t, x, v, a1_);
      xs_.resize(n);
      vs_.resize(n);
      a2_.resize(n);
      const double hh = 0.5 * h;
      set_sum_scaled(flat(xs_), flat(x), hh, flat(v), m);   // xs = x + h/2 v
      set_sum_scaled(flat(vs_), flat(v), hh, flat(a1_), m); // vs = v + h/2 a1
      accel(t + hh, xs_, vs_, a2_);
      add_scaled(flat(x), h, flat(vs_), m);  // x += h vs
      add_scaled(flat(v), h, flat(a2_), m);  // v += h a2
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
      set_sum_scaled(flat(xs_), flat(x), hh, flat(v), m);
      set_sum_scaled(flat(v2_), flat(v), hh, flat(a1_), m);
      accel(t + hh, xs_, v2_, a2_);
      set_sum_scaled(flat(xs_), flat(x), hh, flat(v2_), m);
      set_sum_scaled(flat(v3_), flat(v), hh, flat(a2_), m);
      accel(t + hh, xs_, v3_, a3_);
      set_sum_scaled(flat(xs_), flat(x), h, flat(v3_), m);
      set_sum_scaled(flat(v4_), flat(v), h, flat(a3_), m);
      accel(t + h, xs_, v4_, a4_);
      const double h6 = h / 6.0;
      add_rk4(flat(x), h6, flat(v), flat(v2_), flat(v3_), flat(v4_), m);
      add_rk4(flat(v), h6, flat(a1_), flat(a2_), flat(a3_), flat(a4_), m);
      return;
    }
  }
}

}  // namespace tecido
