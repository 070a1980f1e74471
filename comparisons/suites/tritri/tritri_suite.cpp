#include "comparisons/suites/tritri/tritri_suite.h"

#include "comparisons/engines/outside/outside_engines.h"
#include "comparisons/io/atomic_file.h"
#include "comparisons/suites/agreement/block_result.h"
#include "comparisons/suites/agreement/disagreement_page.h"
#include "comparisons/suites/agreement/disagreements.h"
#include "comparisons/suites/agreement/replay.h"
#include "comparisons/suites/tritri/case_index.h"
#include "comparisons/suites/tritri/check_plan.h"
#include "comparisons/suites/tritri/tritri_case.h"
#include "comparisons/suites/tritri/tritri_report.h"

#include <filesystem>
#include <memory>
#include <stdexcept>

namespace tecido::suites {

namespace {

using agreement::AgreementTable;
using tritri::Family;

constexpr const char* kReferee = "exact";
constexpr const char* kDisagreementFile = "tritri/disagreements.json";

/// What the cases and the assembly share; built from the context alone, before any case runs.
struct Plan {
  tritri::Settings settings;
  std::uint64_t seed = 0;  ///< of the pairs
  std::vector<Family> families;
  std::vector<TriTriEngine> engines;
  std::vector<outside::OutsideEnginePtr> outside;  ///< after `engines` in every case's results
  const TriTriEngine* referee = nullptr;  ///< into engines
  std::vector<tritri::CaseRange> cases;
  CheckList checks;
};

std::vector<std::string> outside_names(const Plan& plan) {
  std::vector<std::string> names;
  for (const auto& e : plan.outside) names.push_back(e->name());
  return names;
}

std::vector<std::string> engine_names(const Plan& plan) {
  std::vector<std::string> names;
  for (const TriTriEngine& e : plan.engines) names.push_back(e.name);
  for (auto& n : outside_names(plan)) names.push_back(std::move(n));
  return names;
}

/// Each engine's door option, in engine_names() order ("" for a built-in engine).
std::vector<std::string> door_options(const Plan& plan) {
  std::vector<std::string> doors(plan.engines.size());
  for (const auto& e : plan.outside) doors.push_back(e->door_option());
  return doors;
}

std::shared_ptr<Plan> make_plan(const SuiteContext& ctx, const tritri::Settings& settings, std::vector<Family> families,
                                std::vector<TriTriEngine> engines, std::vector<outside::OutsideEnginePtr> outside) {
  auto plan = std::make_shared<Plan>();
  plan->settings = settings;
  plan->seed = substream(ctx.seed, 2);
  plan->families = std::move(families);
  plan->engines = std::move(engines);
  plan->outside = std::move(outside);
  for (const TriTriEngine& e : plan->engines)
    if (e.name == kReferee) plan->referee = &e;
  if (!plan->referee) return plan;
  plan->cases = tritri::case_ranges(plan->settings, plan->families);
  plan->checks =
      tritri::declare_checks(plan->families, engine_names(*plan), kReferee, *ctx.tolerances, outside_names(*plan));
  return plan;
}

/// Each declared check gets its family's agreement, or fails with the family's error.
void record(CheckList& checks, const Plan& plan, const AgreementTable& table) {
  const std::vector<std::string> names = engine_names(plan);
  for (std::size_t e = 0; e < names.size(); ++e) {
    for (std::size_t f = 0; f < plan.families.size(); ++f) {
      const std::string name = tritri::check_name(names[e], plan.families[f].name);
      if (!checks.declared(name)) continue;
      if (!table.error[f].empty()) {
        checks.fail(name, table.error[f]);
      } else {
        checks.set(name, table.tally[f][e].rate());
      }
    }
  }
}

SuiteResult assemble(const Plan& plan, const SuiteContext& ctx, const std::vector<io::Json>& results) {
  SuiteResult res;
  res.name = "tritri";
  if (!plan.referee) {
    // The registry always holds the exact referee (the reference engines are always built).
    throw std::logic_error("tritri: the exact referee is not registered");
  }
  AgreementTable table = agreement::empty_table(plan.families.size(), engine_names(plan));
  for (std::size_t k = 0; k < results.size(); ++k) {
    const agreement::CaseRange& range = plan.cases.at(k);
    agreement::add_block(table, range, plan.families.at(range.family).random, results[k]);
  }
  CheckList checks = plan.checks;
  record(checks, plan, table);
  const std::vector<agreement::Disagreement> kept_d = agreement::kept_disagreements(table, plan.settings.max_disagreements);
  auto kept = agreement::disagreement_cases<io::TriPair>(
      table, kept_d, [&plan](std::size_t f, long k) { return tritri::family_pair(plan.seed, f, plan.families.at(f), k); });
  std::vector<std::string> kept_ids;
  for (std::size_t k = 0; k < kept.size(); ++k) kept[k].truth = kept_d[k].truth.hit, kept_ids.push_back(kept[k].id);
  io::Json doc = io::tri_pairs_to_json(kept);
  agreement::label_entries(doc, "pairs", table.engines, kept_d, nullptr);
  const std::string path = ctx.out_dir + "/" + kDisagreementFile;
  io::write_file_atomic(path, doc.dump() + "\n");
  res.views = agreement::write_disagreement_page(ctx.out_dir, kDisagreementFile, "tritri", "pairs", doc);
  const auto per_engine = agreement::table_disagreements(table, door_options(plan), kept_d, kept_ids);
  const agreement::ReplayCommand replay{"tecido tritri", "--pairs"};
  res.stderr_lines =
      agreement::stderr_lines("tritri", replay, std::filesystem::absolute(path).lexically_normal().string(), per_engine);
  res.markdown = tritri::method_markdown(plan.settings, ctx.seed, kReferee, plan.families) +
                 tritri::outside_markdown(plan.outside) + tritri::agreement_table(plan.families, table) + "\n" +
                 tritri::conclusions_markdown(plan.families, table, kReferee, outside_names(plan)) +
                 tritri::disagreements_markdown(kept.size(), agreement::disagreements_found(table), kDisagreementFile) +
                 agreement::replay_markdown(replay, std::string("DIR/") + kDisagreementFile, per_engine);
  res.data = tritri::table_json(plan.families, table);
  res.checks = checks.finish();
  return res;
}

}  // namespace

Sweep tritri_sweep_for(const SuiteContext& ctx, const tritri::Settings& settings, std::vector<Family> families,
                       std::vector<TriTriEngine> engines, std::vector<outside::OutsideEnginePtr> outside) {
  std::shared_ptr<const Plan> plan =
      make_plan(ctx, settings, std::move(families), std::move(engines), std::move(outside));
  Sweep s;
  s.cases = plan->cases.size();
  s.run_case = [plan](std::size_t k) {
    return tritri::run_tritri_case(plan->seed, plan->families, plan->cases.at(k), *plan->referee, plan->engines,
                                   plan->settings.max_disagreements, plan->outside);
  };
  const SuiteContext c = ctx;
  s.assemble = [plan, c](const std::vector<io::Json>& results) { return assemble(*plan, c, results); };
  return s;
}

Sweep tritri_sweep(const SuiteContext& ctx) {
  std::vector<TriTriEngine> engines;
  for (const TriTriEngine& e : tri_tri_engines())
    if (e.name == kReferee || ctx.selects(e.name)) engines.push_back(e);
  std::vector<outside::OutsideEnginePtr> outside;
  if (ctx.outside)
    for (const auto& e : ctx.outside->with(&outside::Capabilities::tri_tri))
      if (ctx.selects(e->name())) outside.push_back(e);
  return tritri_sweep_for(ctx, tritri::settings(ctx.quick), tritri::families(), std::move(engines), std::move(outside));
}

SuiteResult run_tritri_suite(const SuiteContext& ctx) { return run_sweep(&tritri_sweep, ctx, "tritri"); }

}  // namespace tecido::suites
