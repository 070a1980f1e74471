#include "comparisons/suites/order/order_engines.h"

#include "comparisons/engines/core_dynamics.h"
#include "comparisons/engines/outside/outside_engines.h"

#include <stdexcept>

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

OrderEngine outside_order_engine(const outside::OutsideEnginePtr& engine) {
  OrderEngine e{engine->name(), engine->claimed_order().value_or(0.0), {}, true};
  e.make = [engine](const Scene& scene) {
    outside::Creation c = engine->create(scene);
    if (!c.simulation) throw std::runtime_error(outside::not_modelled_line(engine->name(), c.refusal));
    return std::move(c.simulation);
  };
  return e;
}

std::vector<OrderEngine> order_engines(const SuiteContext& ctx) {
  std::vector<OrderEngine> all = core_order_engines();
  if (ctx.outside)
    for (const auto& e : ctx.outside->with(&outside::Capabilities::dynamics)) all.push_back(outside_order_engine(e));
  std::vector<OrderEngine> out;
  for (OrderEngine& e : all)
    if (ctx.selects(e.name)) out.push_back(std::move(e));
  return out;
}

}  // namespace tecido::suites::order
