#include "comparisons/suites/stability/stability_suite.h"

#include "comparisons/engines/dynamics_engines.h"
#include "comparisons/suites/stability/checks.h"
#include "comparisons/suites/stability/extremes_notes.h"
#include "comparisons/suites/stability/stability_report.h"
#include "comparisons/suites/stability/tables.h"

#include <memory>

namespace tecido::suites::stability {

Plan make_plan(const SuiteContext& ctx, Settings s, std::vector<ExtremeGroup> groups) {
  Plan plan;
  plan.layout = layout(s, groups.size());
  plan.checks = declare_checks(s, groups, *ctx.tolerances);
  plan.bands = verdict_bands(*ctx.tolerances);
  engines::DynamicsSources outside_only;  // core's integrators are the settings' bounded and growers
  outside_only.outside = true;
  std::vector<outside::OutsideEnginePtr> chosen;
  for (const engines::DynamicsEntry& e : engines::dynamics_engines(outside_only, ctx.outside.get()))
    if (ctx.selects(e.name)) chosen.push_back(e.outside_engine);
  plan.outside = outside_plan(s, std::move(chosen));
  declare_outside_checks(plan.checks, plan.outside, *ctx.tolerances);
  plan.settings = std::move(s);
  plan.groups = std::move(groups);
  return plan;
}

namespace {

void record_grid(CheckList& checks, const GridTable& t) {
  record(checks, check_name(t.kind, "h_omega_ratio_min"), t.ratio, t.ratio.lo());
  record(checks, check_name(t.kind, "h_omega_ratio_max"), t.ratio, t.ratio.hi());
  record(checks, check_name(t.kind, "grid_spread"), t.h_omega, t.h_omega.spread());
}

/// The grid, growth and horizon tables: their Markdown, data and checks.
std::string oscillator_tables(Plan& plan, const std::vector<io::Json>& results, io::Json& data) {
  const Settings& s = plan.settings;
  std::string md = grid_heading(s);
  for (std::size_t k = 0; k < s.bounded.size(); ++k) {
    const GridTable t = grid_table(s, plan.layout, k, results);
    record_grid(plan.checks, t);
    data["max_step"][integrator_name(t.kind)] = grid_data(t);
    md += grid_markdown(s, t);
  }
  std::vector<GrowthTable> growth;
  std::vector<HorizonTable> horizon;
  for (std::size_t g = 0; g < s.growers.size(); ++g) {
    growth.push_back(growth_table(s, plan.layout, g, results));
    horizon.push_back(horizon_table(s, plan.layout, g, results));
    const IntegratorKind k = s.growers[g];
    record(plan.checks, check_name(k, "growth_rel_error"), growth.back().worst, growth.back().worst.hi());
    record(plan.checks, check_name(k, "horizon_ratio_min"), horizon.back().ratio, horizon.back().ratio.lo());
    record(plan.checks, check_name(k, "horizon_ratio_max"), horizon.back().ratio, horizon.back().ratio.hi());
    data["growth"][integrator_name(k)] = growth_data(growth.back());
    data["horizon"][integrator_name(k)] = horizon_data(horizon.back());
  }
  return md + growth_markdown(s, growth) + horizon_markdown(s, horizon);
}

/// One group's result: its rows, data and check values; a group that threw fails its checks.
void take_group(Plan& plan, std::size_t i, const io::Json& result, std::vector<ExtremeRow>& rows, io::Json& data) {
  const ExtremeGroup& g = plan.groups[i];
  if (const std::string* err = case_error(result)) {
    for (const CheckSpec& c : g.checks(plan.settings)) plan.checks.fail_pending(c.name, g.name + " group: " + *err);
    rows.push_back({g.name, "(the group itself)", "exception", "broke: " + *err, {}});
    return;
  }
  const ExtremeResult r = result_from_json(result);
  for (const Outcome& o : r.outcomes) {
    if (o.reason.empty()) {
      plan.checks.set(o.check, o.value);
    } else {
      plan.checks.fail(o.check, o.reason);
    }
  }
  rows.insert(rows.end(), r.rows.begin(), r.rows.end());
  for (auto it = r.data.begin(); it != r.data.end(); ++it) data[it.key()] = it.value();
}

std::string extremes(Plan& plan, const std::vector<io::Json>& results, io::Json& data) {
  std::vector<ExtremeRow> rows;
  for (std::size_t i = 0; i < plan.groups.size(); ++i)
    take_group(plan, i, results.at(case_index(plan.layout, {CaseGroup::Extremes, i})), rows, data);
  data["extremes"] = io::Json::array();
  for (const ExtremeRow& r : rows)
    data["extremes"].push_back({{"group", r.group}, {"case", r.label}, {"measured", r.measured}, {"verdict", verdict(r, plan.bands)}});
  return extremes_markdown(rows, plan.bands) + extremes_notes(plan.settings, data, plan.bands);
}

}  // namespace

SuiteResult assemble(const Plan& plan_in, const std::vector<io::Json>& results) {
  Plan plan = plan_in;  // the checks get their values here
  SuiteResult res;
  res.name = "stability";
  std::string md = settings_markdown(plan.settings) + method_markdown(plan.settings);
  md += oscillator_tables(plan, results, res.data);
  md += extremes(plan, results, res.data);
  const std::vector<io::Json> outside(results.begin() + static_cast<std::ptrdiff_t>(case_count(plan.layout)), results.end());
  md += outside_tables(plan.outside, outside, plan.checks, res.data);
  res.markdown = md;
  res.checks = plan.checks.finish();
  return res;
}

}  // namespace tecido::suites::stability

namespace tecido::suites {

Sweep stability_sweep_for(const SuiteContext& ctx, stability::Settings s, std::vector<stability::ExtremeGroup> groups) {
  auto plan = std::make_shared<const stability::Plan>(stability::make_plan(ctx, std::move(s), std::move(groups)));
  Sweep sweep;
  const std::size_t own = stability::case_count(plan->layout);
  sweep.cases = own + plan->outside.cases();
  sweep.run_case = [plan, own](std::size_t k) {
    if (k >= own) return stability::run_outside_case(plan->outside, k - own);
    return stability::run_case(plan->settings, plan->groups, plan->layout, k);
  };
  sweep.assemble = [plan](const std::vector<io::Json>& results) { return stability::assemble(*plan, results); };
  return sweep;
}

Sweep stability_sweep(const SuiteContext& ctx) {
  return stability_sweep_for(ctx, stability::settings(ctx.quick), stability::extreme_groups());
}

SuiteResult run_stability_suite(const SuiteContext& ctx) { return run_sweep(&stability_sweep, ctx, "stability"); }

}  // namespace tecido::suites
