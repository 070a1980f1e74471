#include "comparisons/suites/selfcollision/selfcollision_suite.h"

#include "comparisons/engines/outside/outside_engines.h"
#include "comparisons/io/atomic_file.h"
#include "comparisons/suites/agreement/disagreement_page.h"

#include "comparisons/suites/selfcollision/check_plan.h"
#include "comparisons/suites/selfcollision/selfcollision_case.h"
#include "comparisons/suites/selfcollision/selfcollision_report.h"

#include <fmt/format.h>

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
  std::string out_dir;  ///< where selfcollision/disagreements.json and its page go
  std::vector<FrameSource> sources;
  std::vector<SelfCollisionEngine> engines;
  std::vector<outside::OutsideEnginePtr> outside;  ///< scored after `engines`
  std::vector<std::string> engine_names;
  const SelfCollisionEngine* truth = nullptr;  ///< into engines
  CheckList checks;
};

std::shared_ptr<Plan> make_plan(const SuiteContext& ctx, const selfcollision::Settings& settings,
                                std::vector<FrameSource> sources, std::vector<SelfCollisionEngine> engines,
                                std::vector<outside::OutsideEnginePtr> outside) {
  auto plan = std::make_shared<Plan>();
  plan->outside = std::move(outside);
  plan->settings = settings;
  plan->data_dir = ctx.data_dir;
  plan->out_dir = ctx.out_dir;
  plan->sources = std::move(sources);
  plan->engines = std::move(engines);
  for (const char* name : {"exact", "core-brute"})
    for (const SelfCollisionEngine& e : plan->engines)
      if (!plan->truth && e.name == name) plan->truth = &e;
  if (!plan->truth) throw std::logic_error("selfcollision: no truth engine (exact or core-brute) among the engines");
  for (const SelfCollisionEngine& e : plan->engines) plan->engine_names.push_back(e.name);
  std::vector<std::string> outside_names;
  for (const auto& e : plan->outside) outside_names.push_back(e->name());
  for (const auto& n : outside_names) plan->engine_names.push_back(n);
  plan->checks = selfcollision::declare_checks(plan->sources, plan->engine_names, plan->truth->name, *ctx.tolerances,
                                               outside_names);
  return plan;
}

/// Each outside engine's door and how it runs here ("" when there is none).
std::string outside_markdown(const Plan& plan) {
  std::string md;
  for (const auto& e : plan.outside)
    md += "- `" + e->name() + "`: " + e->door() + (e->is_process() ? " (its time includes the round trips of its door)" : "") +
          "\n";
  if (md.empty()) return md;
  return "Outside engines answering tri_tri run as self-collision engines: each frame's candidate pairs from core's "
         "broad phase (boxes overlap, no shared vertex) go to the engine in one batch, and the pairs it calls "
         "intersecting are its answer; checked like core (precision and recall at least /selfcollision/outside_min):\n\n" +
         md + "\n";
}

const char* const kDisagreementFile = "selfcollision/disagreements.json";

/// Writes OUT/selfcollision/disagreements.json and its page; returns the report's paragraph.
std::string write_disagreements(const Plan& plan, const std::vector<SourceScore>& scores, std::vector<PageLink>& views) {
  std::vector<selfcollision::KeptDisagreements> kept;
  long found = 0, written = 0;
  for (const SourceScore& sc : scores) {
    kept.push_back(sc.disagreements);
    found += sc.disagreements.found;
    written += static_cast<long>(sc.disagreements.kept.size());
  }
  const io::Json doc = selfcollision::disagreements_json(plan.sources, kept, plan.truth->name, plan.settings);
  io::write_file_atomic(plan.out_dir + "/" + kDisagreementFile, doc.dump() + "\n");
  const io::Json page = selfcollision::disagreements_page_doc(doc);
  views = agreement::write_disagreement_page(plan.out_dir, kDisagreementFile, "selfcollision", "entries", doc, &page);
  return fmt::format(
      "{} of {} frames of an engine whose pairs differ from `{}`'s are in `{}` (at most {} per source, each with the "
      "frame's positions, the true pairs the engine missed and the pairs it reported that are not true, at most {} "
      "of each); `selfcollision/disagreements.html` draws them.\n\n",
      written, found, plan.truth->name, kDisagreementFile, plan.settings.max_entries_per_source,
      plan.settings.max_pairs_per_list);
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
  res.markdown = selfcollision::method_markdown(plan.settings, plan.sources, scores, truth) + outside_markdown(plan) +
                 selfcollision::score_table(plan.sources, scores) + "\n" +
                 selfcollision::conclusions_markdown(plan.sources, scores, truth) + "\n" +
                 write_disagreements(plan, scores, res.views);
  res.data = selfcollision::scores_json(plan.sources, scores);
  res.checks = checks.finish();
  return res;
}

}  // namespace

Sweep selfcollision_sweep_for(const SuiteContext& ctx, const selfcollision::Settings& settings,
                              std::vector<FrameSource> sources, std::vector<SelfCollisionEngine> engines,
                              std::vector<outside::OutsideEnginePtr> outside) {
  std::shared_ptr<const Plan> plan = make_plan(ctx, settings, std::move(sources), std::move(engines), std::move(outside));
  Sweep s;
  s.cases = plan->sources.size();
  s.run_case = [plan](std::size_t k) {
    return selfcollision::source_score_json(
        selfcollision::score_source(plan->sources.at(k), plan->settings, plan->data_dir, *plan->truth, plan->engines,
                                    plan->outside));
  };
  s.assemble = [plan](const std::vector<io::Json>& results) { return assemble(*plan, results); };
  return s;
}

Sweep selfcollision_sweep(const SuiteContext& ctx) {
  // --engines selects the engines; the truth (exact, or core-brute without the reference build) always runs.
  const bool exact_built = find_self_collision_engine("exact") != nullptr;
  std::vector<SelfCollisionEngine> engines;
  for (const SelfCollisionEngine& e : self_collision_engines())
    if (ctx.selects(e.name) || e.name == (exact_built ? "exact" : "core-brute")) engines.push_back(e);
  std::vector<outside::OutsideEnginePtr> outside;
  if (ctx.outside)
    for (const auto& e : ctx.outside->with(&outside::Capabilities::tri_tri))
      if (ctx.selects(e->name())) outside.push_back(e);
  return selfcollision_sweep_for(ctx, selfcollision::settings(ctx.quick), selfcollision::frame_sources(),
                                 std::move(engines), std::move(outside));
}

SuiteResult run_selfcollision_suite(const SuiteContext& ctx) {
  return run_sweep(&selfcollision_sweep, ctx, "selfcollision");
}

}  // namespace tecido::suites
