#include "comparisons/suites/selfcollision/selfcollision_suite.h"

#include "comparisons/suites/selfcollision/check_plan.h"
#include "comparisons/suites/selfcollision/selfcollision_case.h"
#include "comparisons/suites/selfcollision/selfcollision_report.h"

#include <memory>
#include <stdexcept>

namespace tecido::suites {

namespace {

using selfcollision::FrameSource;
using selfcollision::SourceScore;

/// What the cases and the assembly share; built from the context alone, before any case runs.
struct Plan {
  selfcollision::Settings settings;
  std::string data_dir;
  std::vector<FrameSource> sources;
  std::vector<SelfCollisionEngine> engines;
  std::vector<std::string> engine_names;
  const SelfCollisionEngine* truth = nullptr;  ///< into engines
  CheckList checks;
};

std::shared_ptr<Plan> make_plan(const SuiteContext& ctx, const selfcollision::Settings& settings,
                                std::vector<FrameSource> sources, std::vector<SelfCollisionEngine> engines) {
  auto plan = std::make_shared<Plan>();
  plan->settings = settings;
  plan->data_dir = ctx.data_dir;
  plan->sources = std::move(sources);
  plan->engines = std::move(engines);
  for (const char* name : {"exact", "core-brute"})
    for (const SelfCollisionEngine& e : plan->engines)
      if (!plan->truth && e.name == name) plan->truth = &e;
  if (!plan->truth) throw std::logic_error("selfcollision: no truth engine (exact or core-brute) among the engines");
  for (const SelfCollisionEngine& e : plan->engines) plan->engine_names.push_back(e.name);
  plan->checks = selfcollision::declare_checks(plan->sources, plan->engine_names, plan->truth->name, *ctx.tolerances);
  return plan;
}

SuiteResult assemble(const Plan& plan, const std::vector<io::Json>& results) {
  std::vector<SourceScore> scores;
  CheckList checks = plan.checks;
  for (std::size_t k = 0; k < plan.sources.size(); ++k) {
    scores.push_back(selfcollision::source_score_from_json(results.at(k)));
    selfcollision::record_checks(checks, plan.sources[k].name, plan.engine_names, scores.back());
  }
  SuiteResult res;
  res.name = "selfcollision";
  const std::string& truth = plan.truth->name;
  res.markdown = selfcollision::method_markdown(plan.settings, plan.sources, scores, truth) +
                 selfcollision::score_table(plan.sources, scores) + "\n" +
                 selfcollision::conclusions_markdown(plan.sources, scores, truth);
  res.data = selfcollision::scores_json(plan.sources, scores);
  res.checks = checks.finish();
  return res;
}

}  // namespace

Sweep selfcollision_sweep_for(const SuiteContext& ctx, const selfcollision::Settings& settings,
                              std::vector<FrameSource> sources, std::vector<SelfCollisionEngine> engines) {
  std::shared_ptr<const Plan> plan = make_plan(ctx, settings, std::move(sources), std::move(engines));
  Sweep s;
  s.cases = plan->sources.size();
  s.run_case = [plan](std::size_t k) {
    return selfcollision::source_score_json(
        selfcollision::score_source(plan->sources.at(k), plan->settings, plan->data_dir, *plan->truth, plan->engines));
  };
  s.assemble = [plan](const std::vector<io::Json>& results) { return assemble(*plan, results); };
  return s;
}

Sweep selfcollision_sweep(const SuiteContext& ctx) {
  return selfcollision_sweep_for(ctx, selfcollision::settings(ctx.quick), selfcollision::frame_sources(),
                                 self_collision_engines());
}

SuiteResult run_selfcollision_suite(const SuiteContext& ctx) {
  return run_sweep(&selfcollision_sweep, ctx, "selfcollision");
}

}  // namespace tecido::suites
