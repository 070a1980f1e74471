#include "comparisons/suites/obstacles/obstacles_suite.h"

#include "comparisons/suites/obstacles/cases.h"
#include "comparisons/suites/obstacles/check_plan.h"
#include "comparisons/suites/obstacles/obstacles_report.h"
#include "comparisons/suites/obstacles/settings.h"

#include <memory>

namespace tecido::suites {

namespace {

struct Plan {
  obstacles::Settings settings;
  std::vector<obstacles::Case> cases;
  CheckList checks;  ///< declared from the settings and the tolerance file, before any case runs
};

SuiteResult assemble(const Plan& plan, const std::vector<io::Json>& results) {
  CheckList checks = plan.checks;
  io::Json by_name = io::Json::object();
  for (std::size_t k = 0; k < plan.cases.size(); ++k) {
    obstacles::record(checks, plan.settings, plan.cases[k], results.at(k));
    by_name[plan.cases[k].name] = results.at(k);
  }
  obstacles::record_matched(checks, plan.settings, by_name);
  SuiteResult res;
  res.name = "obstacles";
  const obstacles::Settings& s = plan.settings;
  res.markdown = obstacles::method_markdown(s) + obstacles::analytic_markdown(s, by_name) +
                 obstacles::fast_markdown(s, by_name) + obstacles::block_markdown(s, by_name) +
                 obstacles::bullet_markdown(s, by_name);
  res.data = by_name;
  res.checks = checks.finish();
  return res;
}

}  // namespace

Sweep obstacles_sweep(const SuiteContext& ctx) {
  const obstacles::Settings s = obstacles::settings(ctx.quick);
  auto plan = std::make_shared<const Plan>(Plan{s, obstacles::cases(s, ctx.data_dir), obstacles::declare_checks(s, *ctx.tolerances, true)});
  Sweep sw;
  sw.cases = plan->cases.size();
  sw.run_case = [plan](std::size_t k) { return plan->cases.at(k).run(); };
  sw.assemble = [plan](const std::vector<io::Json>& results) { return assemble(*plan, results); };
  return sw;
}

SuiteResult run_obstacles_suite(const SuiteContext& ctx) { return run_sweep(&obstacles_sweep, ctx, "obstacles"); }

}  // namespace tecido::suites
