#include "comparisons/suites/order/order_engines.h"

#include "comparisons/engines/core_dynamics.h"

namespace tecido::suites::order {

std::vector<OrderEngine> core_order_engines() {
  struct Kind {
    IntegratorKind k;
    double order;
  };
  const Kind kinds[] = {{IntegratorKind::Euler, 1.0}, {IntegratorKind::Symplectic, 1.0},
                        {IntegratorKind::Midpoint, 2.0}, {IntegratorKind::RK4, 4.0}};
  std::vector<OrderEngine> out;
  for (const Kind& kind : kinds) {
    const IntegratorKind k = kind.k;
    out.push_back({integrator_name(k), kind.order, [k](const Scene& scene) {
                     Scene s = scene;
                     s.integrator = k;
                     return std::unique_ptr<reference::DynamicsEngine>(new engines::CoreDynamics(s));
                   }});
  }
  return out;
}

}  // namespace tecido::suites::order
