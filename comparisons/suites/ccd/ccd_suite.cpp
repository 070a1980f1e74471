#include "comparisons/suites/ccd/ccd_suite.h"

#include "comparisons/engines/ccd_engines.h"
#include "comparisons/io/atomic_file.h"
#include "comparisons/suites/ccd/ccd_report.h"
#include "comparisons/suites/ccd/disagreements.h"
#include "comparisons/suites/ccd/family_case.h"
#include "comparisons/suites/ccd/families.h"
#include "comparisons/suites/ccd/sheet_through_sheet.h"

#include "comparisons/suites/agreement/disagreement_page.h"
#include "comparisons/suites/agreement/replay.h"

#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <stdexcept>

namespace tecido::suites {

namespace {

using ccd::Family;
using ccd::FamilyResult;

std::string check_name(const Family& f, const std::string& engine, const std::string& what) {
  return "ccd/" + ccd::family_name(f) + "/" + engine + "/" + what;
}

struct Plan {
  ccd::Settings settings;
  ccd::SheetSettings sheet;
  std::uint64_t seed = 0;
  bool referee = false;  ///< the exact referee is built (otherwise nothing runs)
  std::vector<ccd::SuiteEngine> engines;  ///< the referee and the selected engines (suite_engines.h)
  bool sheet_runs = false;  ///< the sheet-through-sheet group runs (it measures core: when core is selected)
  CheckList checks;      ///< declared from the family table, the engines and the tolerance file, before any case runs

  bool runs(const std::string& name) const {
    for (const auto& e : engines)
      if (e.name == name) return true;
    return false;
  }
  std::vector<std::string> engine_names() const {
    std::vector<std::string> names;
    for (const auto& e : engines) names.push_back(e.name);
    return names;
  }
};

/// What the late-toi checks measure, and why it matters.
const char* const kLateNote =
    "largest toi - t* where both hit: how much later than the referee's first contact the engine reports it (a "
    "late toi lets a simulation tunnel, as a miss does)";

/// An outside engine's checks on family f: on random motion only, like the reference engines
/// (the adversarial families are reported), and only on the kind it models.
void declare_outside(CheckList& c, const Tolerances& tol, const Family& f, const ccd::SuiteEngine& e) {
  if (!f.checks_references || !e.models(f.kind)) return;
  c.declare(check_name(f, e.name, "false_negative_rate"), tol.at_most("/ccd/outside_random_max_fn_rate"),
            "share of contacts missed");
  c.declare(check_name(f, e.name, "false_positive_rate"), tol.at_most("/ccd/outside_random_max_fp_rate"),
            "share of non-contacts called hits");
  c.declare(check_name(f, e.name, "unanswered_rate"), tol.at_most("/ccd/outside_random_max_unanswered_rate"),
            "share of queries answered null (cannot say)");
  c.declare(check_name(f, e.name, "max_toi_late"), tol.at_most("/ccd/outside_random_max_toi_late"), kLateNote);
}

/// The checks of one family (see ccd_suite.h), for the engines the plan runs.
void declare_family(CheckList& c, const Tolerances& tol, const Family& f, const Plan& p) {
  if (p.runs("core")) {
    c.declare(check_name(f, "core", "false_negatives"), tol.at_most("/ccd/core_false_negatives"), "contacts core missed");
    c.declare(check_name(f, "core", "toi_after_exact"), tol.at_most("/ccd/core_toi_after_exact"),
              "core hits whose toi is certainly after the referee's first contact");
  }
  if (f.constructed)
    c.declare(check_name(f, "exact", "known_mismatches"), tol.at_most("/ccd/exact_known_mismatches"),
              "queries where the referee differs from the constructed answer (hit, or toi)");
  c.declare(check_name(f, "exact", "unfiltered_mismatches"), tol.at_most("/ccd/exact_unfiltered_mismatches"),
            "queries where the referee differs from itself without its floating-point filter");
  for (const ccd::SuiteEngine& e : p.engines)
    if (e.is_outside()) declare_outside(c, tol, f, e);
  if (!f.checks_references) return;
  if (p.runs("core")) {
    c.declare(check_name(f, "core", "false_positive_rate"), tol.at_most("/ccd/core_random_max_fp_rate"),
              "share of non-contacts core calls hits");
    c.declare(check_name(f, "core", "max_toi_error"), tol.at_most("/ccd/core_random_max_toi_error"),
              "max t* - toi where both hit");
  }
  std::vector<std::string> refs;
  if (p.runs("fcl")) refs.push_back("fcl");
  if (f.kind == CcdKind::VertexFace && p.runs("bullet")) refs.push_back("bullet");  // Bullet has no edge-edge test
  for (const std::string& e : refs) {
    c.declare(check_name(f, e, "false_negative_rate"), tol.at_most("/ccd/" + e + "_random_max_fn_rate"),
              "share of contacts missed");
    c.declare(check_name(f, e, "false_positive_rate"), tol.at_most("/ccd/" + e + "_random_max_fp_rate"),
              "share of non-contacts called hits");
    c.declare(check_name(f, e, "max_toi_late"), tol.at_most("/ccd/" + e + "_random_max_toi_late"), kLateNote);
  }
}

const char* const kSheet = "ccd/sheet-through-sheet/";

/// The sheet-through-sheet case group's checks (sheet_through_sheet.h).
void declare_sheet(CheckList& c, const Tolerances& tol) {
  const std::string k = kSheet;
  c.declare(k + "discrete/pairs_in_frames", tol.at_most("/ccd/sheet_discrete_pairs"),
            "intersecting pairs in either frame (core and exact): the pass-through is invisible to discrete detection");
  c.declare(k + "discrete/run_contact_checks", tol.at_most("/ccd/sheet_discrete_pairs"),
            "checks of the discrete, no-response run that found a pair");
  c.declare(k + "none/passed_through", tol.at_least("/ccd/sheet_passed_through", 1.0),
            "1 when the discrete, no-response run ends with the falling sheet below the other");
  c.declare(k + "exact/contacts", tol.at_least("/ccd/sheet_min_contacts"), "the referee's contacts between the frames");
  c.declare(k + "core/missed", tol.at_most("/ccd/core_false_negatives"), "referee's contacts core does not report");
  c.declare(k + "core/extra", tol.at_most("/ccd/sheet_core_extra"), "core's confirmed contacts the referee lacks");
  c.declare(k + "core/candidates_differ_from_brute", tol.at_most("/ccd/sheet_candidates_differ"),
            "pairs in only one of core's broad-phase candidates and core-brute's");
  c.declare(k + "core-brute/missed", tol.at_most("/ccd/core_false_negatives"), "referee's contacts core-brute misses");
  c.declare(k + "impulse/contacts", tol.at_most("/ccd/sheet_impulse_contacts"),
            "the referee's contacts between consecutive frames of the continuous + impulse run");
  c.declare(k + "impulse/steps_completed", tol.at_least("/ccd/sheet_steps_completed", 1.0),
            "share of the run's steps completed (stable)");
}

void record_sheet(CheckList& c, const ccd::SheetResult& r, const ccd::SheetSettings& s) {
  const std::string k = kSheet;
  c.set(k + "discrete/pairs_in_frames", static_cast<double>(r.discrete_pairs));
  c.set(k + "discrete/run_contact_checks", static_cast<double>(r.discrete_run_contacts));
  c.set(k + "none/passed_through", static_cast<double>(r.discrete_passed));
  c.set(k + "exact/contacts", static_cast<double>(r.exact_contacts));
  c.set(k + "core/missed", static_cast<double>(r.core_missed));
  c.set(k + "core/extra", static_cast<double>(r.core_extra));
  c.set(k + "core/candidates_differ_from_brute", static_cast<double>(r.candidates_differ));
  c.set(k + "core-brute/missed", static_cast<double>(r.brute_missed));
  c.set(k + "impulse/contacts", static_cast<double>(r.impulse_contacts));
  c.set(k + "impulse/steps_completed", static_cast<double>(r.impulse_steps) / s.steps);
}

Plan make_plan(const SuiteContext& ctx) {
  Plan p;
  p.settings = ccd::settings(ctx.quick);
  p.sheet = ccd::sheet_settings(ctx.quick);
  p.seed = ctx.seed;
  p.referee = find_ccd_engine("exact") != nullptr;
  if (!p.referee) return p;
  p.engines = ccd::suite_engines(ctx);
  p.sheet_runs = p.runs("core");
  for (const Family& f : ccd::families()) declare_family(p.checks, *ctx.tolerances, f, p);
  if (p.sheet_runs) declare_sheet(p.checks, *ctx.tolerances);
  return p;
}

/// Sets every declared check of family f from its result.
void record(CheckList& c, const Family& f, const FamilyResult& r) {
  for (const ccd::EngineTally& e : r.engines) {
    auto set = [&](const char* what, double value) {
      const std::string n = check_name(f, e.engine, what);
      if (c.declared(n)) c.set(n, value);
    };
    const agreement::Tally& t = e.tally;
    set("false_negatives", static_cast<double>(t.misses));
    set("toi_after_exact", static_cast<double>(e.toi_after));
    set("false_negative_rate", r.fn_rate(e));
    set("false_positive_rate", r.fp_rate(e));
    set("max_toi_error", t.max_t_error);
    set("max_toi_late", e.max_toi_late);
    set("unanswered_rate", t.cases ? static_cast<double>(t.no_answer) / static_cast<double>(t.cases) : 0.0);
  }
  if (c.declared(check_name(f, "exact", "known_mismatches")))
    c.set(check_name(f, "exact", "known_mismatches"), static_cast<double>(r.known_mismatch));
  c.set(check_name(f, "exact", "unfiltered_mismatches"), static_cast<double>(r.unfiltered_mismatch));
}

const char* const kDisagreementFile = "ccd/disagreements.json";

/// Per engine of the plan: its misses and false hits over the families that ran, and the kept ones.
std::vector<agreement::EngineDisagreements> per_engine(const Plan& plan, const std::vector<FamilyResult>& results,
                                                       const std::vector<ccd::KeptDisagreement>& kept) {
  const std::size_t n = plan.engines.size();
  std::vector<std::string> doors(n);
  std::vector<long> misses(n, 0), false_hits(n, 0);
  for (std::size_t e = 0; e < n; ++e)
    if (plan.engines[e].outside) doors[e] = plan.engines[e].outside->door_option();
  for (const FamilyResult& r : results)
    for (std::size_t e = 0; e < r.engines.size() && e < n; ++e)
      misses[e] += r.engines[e].tally.misses, false_hits[e] += r.engines[e].tally.false_hits;
  std::vector<std::size_t> kept_engine;
  std::vector<std::string> kept_ids;
  for (const ccd::KeptDisagreement& k : kept) kept_engine.push_back(k.d.engine), kept_ids.push_back(k.entry.id);
  return agreement::engine_disagreements(plan.engine_names(), doors, misses, false_hits, kept_engine, kept_ids);
}

/// DIR/ccd/disagreements.json from the families' disagreements (their queries regenerated); the
/// report's paragraph, and the per-engine lines for stderr (the file named by its absolute path).
std::string write_disagreements(const Plan& plan, const SuiteContext& ctx, const std::vector<FamilyResult>& results,
                                std::vector<std::string>& stderr_out, std::vector<PageLink>& views) {
  std::vector<ccd::KeptDisagreement> kept;
  const auto& fams = ccd::families();
  for (std::size_t k = 0; k < results.size(); ++k) {
    if (results[k].disagree.empty()) continue;
    const auto queries = ccd::family_queries(k, plan.settings, plan.seed);
    ccd::add_disagreements(ccd::family_name(fams[k]), results[k], queries, plan.engine_names(),
                           plan.settings.max_disagreements, kept);
  }
  const std::string path = ctx.out_dir + "/" + kDisagreementFile;
  const io::Json doc = ccd::disagreements_json(kept, plan.engine_names());
  io::write_file_atomic(path, doc.dump() + "\n");
  views = agreement::write_disagreement_page(ctx.out_dir, kDisagreementFile, "ccd", "queries", doc);
  const std::vector<agreement::EngineDisagreements> engines = per_engine(plan, results, kept);
  const agreement::ReplayCommand replay{"tecido ccd", "--queries"};
  stderr_out = agreement::stderr_lines("ccd", replay, std::filesystem::absolute(path).lexically_normal().string(), engines);
  return fmt::format("{} disagreements with the referee (at most {}) are in `{}` (ids `engine:kind/family/index`; "
                     "each entry names its `engine`, the engine's `answer` and the `referee`'s, hit and toi, and "
                     "carries the referee's hit as `truth`); `tecido ccd --queries DIR/{} --json` re-runs them with "
                     "every engine and prints each one's false positives and negatives.\n\n",
                     kept.size(), plan.settings.max_disagreements, kDisagreementFile, kDisagreementFile) +
         agreement::replay_markdown(replay, std::string("DIR/") + kDisagreementFile, engines);
}

/// The outside engines of the plan that do not model `kind` (their cells read "not modelled").
std::vector<std::string> not_modelled(const Plan& plan, CcdKind kind) {
  std::vector<std::string> names;
  for (const auto& e : plan.engines)
    if (!e.models(kind)) names.push_back(e.name);
  return names;
}

SuiteResult assemble(const Plan& plan_in, const SuiteContext& ctx, const std::vector<io::Json>& results) {
  Plan plan = plan_in;
  SuiteResult res;
  res.name = "ccd";
  if (!plan.referee) {
    // The registry always holds the exact referee (the reference engines are always built).
    throw std::logic_error("ccd: the exact referee is not registered");
  }
  const auto& fams = ccd::families();
  std::vector<FamilyResult> fr(fams.size());
  std::vector<std::string> failed(fams.size());
  for (std::size_t k = 0; k < fams.size(); ++k) {
    if (const std::string* err = case_error(results.at(k))) {
      failed[k] = *err;
      plan.checks.fail_pending("ccd/" + ccd::family_name(fams[k]) + "/", "case threw: " + *err);
      continue;
    }
    fr[k] = ccd::family_result_from_json(results[k]);
    record(plan.checks, fams[k], fr[k]);
  }
  std::string sheet_md;
  if (!plan.sheet_runs) {
    sheet_md = "### A sheet through a sheet\n\nNot run: it measures core's continuous self-collision, and --engines does "
               "not select core.\n\n";
  } else if (const std::string* err = case_error(results.at(fams.size()))) {
    plan.checks.fail_pending(kSheet, "case threw: " + *err);
    sheet_md = "### A sheet through a sheet\n\nfailed: " + *err + "\n\n";
  } else {
    const ccd::SheetResult sr = ccd::sheet_result_from_json(results[fams.size()]);
    record_sheet(plan.checks, sr, plan.sheet);
    sheet_md = ccd::sheet_markdown(sr, plan.sheet);
  }
  const std::vector<std::string> vf_off = not_modelled(plan, CcdKind::VertexFace),
                                 ee_off = not_modelled(plan, CcdKind::EdgeEdge);
  res.markdown = ccd::method_markdown(plan.settings, plan.seed) + ccd::outside_markdown(plan.engines) +
                 ccd::kind_tables(CcdKind::VertexFace, fr, failed, vf_off) +
                 ccd::kind_tables(CcdKind::EdgeEdge, fr, failed, ee_off) + ccd::referee_table(fr, failed) +
                 ccd::conclusions(fr, failed) + write_disagreements(plan, ctx, fr, res.stderr_lines, res.views) + sheet_md;
  res.data = ccd::results_json(fr);
  res.checks = plan.checks.finish();
  return res;
}

}  // namespace

Sweep ccd_sweep(const SuiteContext& ctx) {
  auto plan = std::make_shared<const Plan>(make_plan(ctx));
  Sweep s;
  // the families, then the sheet case group when it runs
  s.cases = plan->referee ? ccd::families().size() + (plan->sheet_runs ? 1 : 0) : 0;
  s.run_case = [plan](std::size_t k) {
    if (k == ccd::families().size()) return ccd::sheet_result_json(ccd::run_sheet_through_sheet(plan->sheet));
    const auto queries = ccd::family_queries(k, plan->settings, plan->seed);
    return ccd::family_result_json(
        ccd::run_family(ccd::family_name(ccd::families()[k]), queries, plan->settings, plan->engines));
  };
  const SuiteContext c = ctx;
  s.assemble = [plan, c](const std::vector<io::Json>& results) { return assemble(*plan, c, results); };
  return s;
}

SuiteResult run_ccd_suite(const SuiteContext& ctx) { return run_sweep(&ccd_sweep, ctx, "ccd"); }

}  // namespace tecido::suites
