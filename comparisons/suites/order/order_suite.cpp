#include "comparisons/suites/order/order_suite.h"

#include "comparisons/suites/order/convergence.h"
#include "comparisons/suites/order/order_report.h"
#include "comparisons/suites/order/settings.h"

#include <fmt/format.h>

#include <memory>

namespace tecido::suites {

namespace {

using order::EngineRuns;
using order::OrderEngine;
using order::Problem;

std::string check_name(const Problem& p, const OrderEngine& e) { return fmt::format("order/{}/{}", p.name, e.name); }

struct Plan {
  order::Settings settings;
  std::vector<Problem> problems;
  std::vector<OrderEngine> engines;
  double band = 0.0;
  CheckList checks;  ///< declared from the settings and the tolerance file, before any case runs
};

Plan make_plan(const SuiteContext& ctx, std::vector<OrderEngine> engines) {
  Plan plan{order::settings(ctx.quick), order::problems(), std::move(engines), ctx.tolerances->get("/order/band"), {}};
  for (const Problem& p : plan.problems)
    for (const OrderEngine& e : plan.engines)
      if (e.claimed_order > 0.0)  // an engine that claims no order is fitted and reported, not checked
        plan.checks.declare(check_name(p, e), ctx.tolerances->around("/order/band", e.claimed_order),
                          fmt::format("fitted order; {} claims {:g}", e.name, e.claimed_order));
  return plan;
}

EngineRuns fitted(const Plan& plan, const OrderEngine& e, const Problem& p, const io::Json& result) {
  EngineRuns r{e.name, e.claimed_order, {}, {}, {}};
  if (const std::string* err = case_error(result)) {
    r.error = *err;
    return r;
  }
  r.samples = order::samples_from_json(result.at("samples"));
  std::vector<double> hs, es;
  for (const order::Sample& s : r.samples) hs.push_back(s.h), es.push_back(s.error);
  const order::Settings& s = plan.settings;
  r.fit = fit_order(hs, es, s.roundoff_floor * p.scale, s.too_big * p.scale, s.agree, s.min_halvings);
  return r;
}

void record(CheckList& checks, const Problem& p, const EngineRuns& r) {
  const std::string name = fmt::format("order/{}/{}", p.name, r.engine);
  if (!checks.declared(name)) return;
  if (!r.error.empty()) {
    checks.fail(name, r.error);
  } else if (r.fit.first < 0) {
    checks.fail(name, "no asymptotic range: fewer than the required agreeing halvings between round-off and blow-up");
  } else {
    checks.set(name, r.fit.slope);
  }
}

/// Euler and midpoint on one problem, when both are among the engines.
order::HeadToHead head_to_head(const Plan& plan, const Problem& p, const std::vector<EngineRuns>& runs) {
  order::HeadToHead h{p.name};
  const int j = plan.settings.head_to_head;
  for (const EngineRuns& r : runs) {
    if (!r.error.empty() || static_cast<int>(r.samples.size()) <= j) continue;
    if (r.engine == "euler") h.euler = r.samples[j].error;
    if (r.engine == "midpoint") h.midpoint = r.samples[j].error, h.midpoint_2h = r.samples[j - 1].error;
  }
  return h;
}

SuiteResult assemble(const Plan& plan_in, const SuiteContext& ctx, const std::vector<io::Json>& results) {
  Plan plan = plan_in;
  SuiteResult res;
  res.name = "order";
  std::string md = order::method_markdown(plan.settings, plan.band) + order::outside_markdown(plan.engines);
  std::vector<order::HeadToHead> h2h;
  std::size_t k = 0;
  for (const Problem& p : plan.problems) {
    std::vector<EngineRuns> runs;
    for (const OrderEngine& e : plan.engines) {
      runs.push_back(fitted(plan, e, p, results.at(k++)));
      record(plan.checks, p, runs.back());
      res.data[p.name][e.name] = order::runs_json(runs.back());
    }
    md += order::fit_table(p, runs) + order::fit_plot(ctx, p, runs, res.plots) + "\n";
    h2h.push_back(head_to_head(plan, p, runs));
  }
  if (plan.engines.empty()) md += "No engine ran: --engines names none of this suite's engines.\n\n";
  res.markdown = md + order::head_to_head_markdown(plan.settings, h2h);
  res.checks = plan.checks.finish();
  return res;
}

}  // namespace

Sweep order_sweep_for(const SuiteContext& ctx, std::vector<OrderEngine> engines) {
  auto plan = std::make_shared<const Plan>(make_plan(ctx, std::move(engines)));
  Sweep s;
  s.cases = plan->problems.size() * plan->engines.size();
  s.run_case = [plan](std::size_t k) {
    const Problem& p = plan->problems[k / plan->engines.size()];
    const OrderEngine& e = plan->engines[k % plan->engines.size()];
    return io::Json{{"samples", order::samples_json(order::convergence_runs(p, e, plan->settings.h0, plan->settings.halvings))}};
  };
  const SuiteContext c = ctx;
  s.assemble = [plan, c](const std::vector<io::Json>& results) { return assemble(*plan, c, results); };
  return s;
}

Sweep order_sweep(const SuiteContext& ctx) { return order_sweep_for(ctx, order::order_engines(ctx)); }

SuiteResult run_order_suite(const SuiteContext& ctx) { return run_sweep(&order_sweep, ctx, "order"); }

}  // namespace tecido::suites
