#include "comparisons/suites/order/order_engines.h"

#include "comparisons/engines/dynamics_engines.h"

namespace tecido::suites::order {

OrderEngine order_engine(const engines::DynamicsEntry& entry) {
  return {entry.name, entry.claimed_order, entry.make, entry.source == engines::DynamicsSource::Outside};
}

std::vector<OrderEngine> order_engines(const SuiteContext& ctx) {
  engines::DynamicsSources sources;
  sources.core = true;
  sources.outside = true;
  std::vector<OrderEngine> out;
  for (const engines::DynamicsEntry& e : engines::dynamics_engines(sources, ctx.outside.get()))
    if (ctx.selects(e.name)) out.push_back(order_engine(e));
  return out;
}

}  // namespace tecido::suites::order
