#pragma once
/// Time integrators over one derivative function (seed section 2.2), so the force model is
/// written once. The state is (x, v) with dx/dt = v and dv/dt = a(t, x, v).
///   euler      explicit Euler, eq. 3: x += h v(t), v += h a(t)                  order 1
///   symplectic semi-implicit Euler, the seed's engine (3.1.1 step 2):
///              v += h a(t), then x += h v(t + h)                               order 1
///   midpoint   eqs. 6-8: k1 = h f(y), y += h f(y + k1/2)                        order 2
///   rk4        classical Runge-Kutta 4                                          order 4
#include "core/geometry/types.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace tecido {

enum class IntegratorKind { Euler, Symplectic, Midpoint, RK4 };

/// "euler", "symplectic", "midpoint", "rk4".
const char* integrator_name(IntegratorKind k);
/// Parses the names above; nothing for an unknown name.
std::optional<IntegratorKind> parse_integrator(const std::string& name);
/// Force evaluations per step: 1, 1, 2, 4.
int evaluations_per_step(IntegratorKind k);

/// a(t, x, v) -> a, written into the last argument (already sized by the caller's use).
using AccelerationFn =
    std::function<void(double t, const std::vector<Vec3>& x, const std::vector<Vec3>& v, std::vector<Vec3>& a)>;

/// Advances (x, v) from time t by h with the chosen method. Keeps scratch buffers between
/// calls so a step allocates nothing once sizes are stable.
class Integrator {
 public:
  explicit Integrator(IntegratorKind kind = IntegratorKind::Symplectic) : kind_(kind) {}
  IntegratorKind kind() const { return kind_; }

  /// In place: x, v at time t become x, v at time t + h.
  void step(const AccelerationFn& accel, double t, double h, std::vector<Vec3>& x, std::vector<Vec3>& v);

 private:
  IntegratorKind kind_;
  std::vector<Vec3> a1_, a2_, a3_, a4_, xs_, vs_, v2_, v3_, v4_;
};

}  // namespace tecido
