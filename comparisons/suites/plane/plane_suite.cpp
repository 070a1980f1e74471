#include "comparisons/suites/plane/plane_suite.h"

#include "comparisons/io/atomic_file.h"
#include "comparisons/suites/agreement/block_result.h"
#include "comparisons/suites/agreement/disagreement_page.h"
#include "comparisons/suites/agreement/disagreements.h"
#include "comparisons/suites/agreement/replay.h"
#include "comparisons/suites/plane/agreement_case.h"
#include "comparisons/suites/plane/check_plan.h"
#include "comparisons/suites/plane/contact_time_report.h"
#include "comparisons/suites/plane/group_tally.h"
#include "comparisons/suites/plane/drop_report.h"
#include "comparisons/suites/plane/plane_report.h"
#include "comparisons/suites/plane/theory.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <stdexcept>

namespace tecido::suites::plane {

namespace {

constexpr const char* kReferee = "exact";
constexpr const char* kDisagreementFile = "plane/disagreements.json";

std::vector<std::string> engine_names(const Plan& plan) {
  std::vector<std::string> names;
  for (const SegmentPlaneEngine& e : plan.engines) names.push_back(e.name);
  return names;
}

}  // namespace

Plan make_plan(const SuiteContext& ctx, Settings s, std::vector<Category> categories,
               const std::vector<SegmentPlaneEngine>& engines) {
  Plan plan;
  plan.settings = std::move(s);
  plan.seed = ctx.seed;
  plan.case_seed = substream(ctx.seed, 1);
  plan.categories = std::move(categories);
  for (const SegmentPlaneEngine& e : engines) {
    if (e.name == kReferee) {
      plan.referee = e;
    } else {
      plan.engines.push_back(e);
    }
  }
  plan.layout = layout(plan.settings, plan.categories, plan.referee.has_value());
  plan.checks = declare_checks(plan.settings, engine_names(plan), plan.referee ? kReferee : "", plan.bullet,
                               *ctx.tolerances);
  return plan;
}

io::Json run_case(const Plan& plan, std::size_t k) {
  const CaseRef c = case_at(plan.layout, k);
  const Settings& s = plan.settings;
  switch (c.group) {
    case CaseGroup::Agreement:
      return run_agreement_case(plan.case_seed, plan.categories, plan.layout.blocks.at(c.i), *plan.referee, plan.engines,
                                s.max_disagreements);
    case CaseGroup::ContactTime: {
      const ContactCell cell = contact_cell(plan.layout, c.i);
      const ContactTimeSettings& ct = s.contact_time;
      return cell_json(run_contact_cell(ct, plan.seed, ct.integrators.at(cell.integrator), ct.steps.at(cell.step),
                                        ct.levels.at(cell.level)));
    }
    case CaseGroup::Drop: return drop_json(run_drop(s.drop, s.drop.heights.at(c.i)));
  }
  return {};
}

namespace {

/// The largest of some values, or the first reason one of them is missing.
struct MaxOrReason {
  double value = 0.0;
  std::string reason;
  void add(double x, const std::string& why_missing) {
    if (!reason.empty()) return;
    if (!why_missing.empty() || std::isnan(x)) {
      reason = why_missing.empty() ? "NaN" : why_missing;
      return;
    }
    value = std::max(value, x);
  }
  void record(CheckList& checks, const std::string& name) const {
    if (!checks.declared(name)) return;
    if (reason.empty()) {
      checks.set(name, value);
    } else {
      checks.fail(name, reason);
    }
  }
};

/// Each declared agreement check gets its group's value, or fails with the reason it has none.
void record_agreement(CheckList& checks, const Plan& plan, const AgreementTable& table) {
  for (std::size_t e = 0; e < plan.engines.size(); ++e) {
    const std::string& name = plan.engines[e].name;
    for (const CategoryGroup& g : category_groups()) {
      const std::string agreement = agreement_check(name, g.name), t_error = t_error_check(name, g.name);
      if (!checks.declared(agreement)) continue;
      const GroupTally gt = group_tally(table, plan.categories, g, e);
      const std::string none = gt.tally.cases == 0 ? "no case in group " + g.name : "";
      const std::string why = !gt.error.empty() ? gt.error : none;
      if (why.empty()) {
        checks.set(agreement, gt.tally.rate());
      } else {
        checks.fail(agreement, why);
      }
      if (!checks.declared(t_error)) continue;
      if (!why.empty()) {
        checks.fail(t_error, why);
      } else if (gt.tally.both_hit == 0) {
        checks.fail(t_error, "no case of group " + g.name + " where both " + name + " and the referee hit");
      } else {
        checks.set(t_error, gt.tally.max_t_error);
      }
    }
  }
}

/// The agreement section: table, conclusions, the disagreement file (labelled, with the replay of
/// each engine, also on stderr); the checks' values.
std::string agreement_section(CheckList& checks, const Plan& plan, const std::string& out_dir,
                              const std::vector<io::Json>& results, io::Json& data,
                              std::vector<std::string>& stderr_out, std::vector<PageLink>& views) {
  AgreementTable table = agreement::empty_table(plan.categories.size(), engine_names(plan));
  for (std::size_t i = 0; i < plan.layout.blocks.size(); ++i) {
    const CaseRange& range = plan.layout.blocks[i];
    agreement::add_block(table, range, plan.categories.at(range.family).random,
                         results.at(case_index(plan.layout, {CaseGroup::Agreement, i})));
  }
  record_agreement(checks, plan, table);
  const std::vector<agreement::Disagreement> kept_d = agreement::kept_disagreements(table, plan.settings.max_disagreements);
  auto kept = agreement::disagreement_cases<io::PlaneCase>(
      table, kept_d, [&plan](std::size_t c, long k) { return category_case(plan.case_seed, c, plan.categories.at(c), k); });
  std::vector<std::string> kept_ids;
  for (std::size_t k = 0; k < kept.size(); ++k) kept[k].truth = kept_d[k].truth.hit, kept_ids.push_back(kept[k].id);
  io::Json doc = io::plane_cases_to_json(kept);
  agreement::label_entries(doc, "cases", table.engines, kept_d, "t");
  const std::string path = out_dir + "/" + kDisagreementFile;
  io::write_file_atomic(path, doc.dump(1) + "\n");
  views = agreement::write_disagreement_page(out_dir, kDisagreementFile, "plane", "cases", doc);
  data["agreement"] = agreement_json(plan.categories, table);
  // The plane suite runs built-in engines only: no door to carry.
  const auto per_engine =
      agreement::table_disagreements(table, std::vector<std::string>(table.engines.size()), kept_d, kept_ids);
  const agreement::ReplayCommand replay{"tecido plane", "--cases"};
  stderr_out =
      agreement::stderr_lines("plane", replay, std::filesystem::absolute(path).lexically_normal().string(), per_engine);
  return agreement_table(plan.categories, table) + agreement_conclusions(plan.categories, table, kReferee) +
         disagreements_markdown(kept.size(), agreement::disagreements_found(table), kDisagreementFile) +
         agreement::replay_markdown(replay, std::string("DIR/") + kDisagreementFile, per_engine);
}

ContactTable contact_table_of(const Plan& plan, const std::vector<io::Json>& results) {
  ContactTable t = empty_contact_table(plan.settings.contact_time);
  for (std::size_t i = 0; i < plan.layout.size(CaseGroup::ContactTime); ++i) {
    const ContactCell c = contact_cell(plan.layout, i);
    const io::Json& r = results.at(case_index(plan.layout, {CaseGroup::ContactTime, i}));
    if (const std::string* err = case_error(r)) t.error[c.integrator][c.step][c.level] = *err;
    else t.cells[c.integrator][c.step][c.level] = cell_from_json(r);
  }
  return t;
}

/// Per checked integrator and step: the worst error over the levels as a multiple of the tolerance.
void record_contact(CheckList& checks, const ContactTimeSettings& s, const ContactTable& t) {
  for (std::size_t i = 0; i < s.integrators.size(); ++i)
    for (std::size_t j = 0; j < s.steps.size(); ++j) {
      MaxOrReason worst;
      for (std::size_t l = 0; l < s.levels.size(); ++l) {
        const ContactCellResult& c = t.cells[i][j][l];
        const std::string why = missing_reason(s, c, t.error[i][j][l]);
        worst.add(c.max_error / c.tolerance, why.empty() ? "" : fmt::format("k = {}: {}", s.levels[l], why));
      }
      worst.record(checks, contact_time_check(s.integrators[i], s.steps[j]));
    }
}

std::string contact_section(CheckList& checks, const Plan& plan, const std::string& out_dir,
                            const std::vector<io::Json>& results, io::Json& data) {
  const ContactTimeSettings& s = plan.settings.contact_time;
  const ContactTable t = contact_table_of(plan, results);
  record_contact(checks, s, t);
  io::write_file_atomic(out_dir + "/plane/contact_time.dat", contact_dat(s, t));
  data["contact_time"] = contact_json(s, t);
  return contact_method(s) + contact_table(s, t) + contact_conclusions(s, t);
}

/// Core's apex error and Bullet's contact-time error, each the worst over the heights.
void record_drop(CheckList& checks, const DropTable& t) {
  MaxOrReason apex, bullet;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const DropRow& r = t.rows[i];
    const std::string at = fmt::format("z0 = {:g} m: ", r.z0);
    const std::string err = t.error[i].empty() ? "" : at + t.error[i];
    apex.add(std::abs(r.apex_core - r.apex_exact) / r.apex_exact,
             !err.empty() ? err : std::isnan(r.apex_core) ? at + "core never touched the floor" : "");
    bullet.add(std::abs(r.t_rigid - r.t_exact),
               !err.empty() ? err : std::isnan(r.t_rigid) ? at + "Bullet's sphere never touched the floor" : "");
  }
  apex.record(checks, kCoreApexCheck);
  bullet.record(checks, kBulletContactCheck);
}

std::string drop_section(CheckList& checks, const Plan& plan, const std::vector<io::Json>& results, io::Json& data) {
  const DropSettings& s = plan.settings.drop;
  DropTable t;
  for (std::size_t i = 0; i < plan.layout.size(CaseGroup::Drop); ++i) {
    const io::Json& r = results.at(case_index(plan.layout, {CaseGroup::Drop, i}));
    const std::string* err = case_error(r);
    t.rows.push_back(err ? DropRow{} : drop_from_json(r));
    t.rows.back().z0 = s.heights.at(i);
    t.error.push_back(err ? *err : "");
  }
  record_drop(checks, t);
  data["drop"] = drop_data(t);
  return drop_method(s, plan.bullet) + drop_table(t, plan.bullet) + drop_conclusions(s, t);
}

}  // namespace

SuiteResult assemble(const Plan& plan, const std::string& out_dir, const std::vector<io::Json>& results) {
  if (results.size() != case_count(plan.layout)) throw std::logic_error("plane: results and cases differ in number");
  CheckList checks = plan.checks;
  SuiteResult res;
  res.name = "plane";
  // The registry always holds the exact referee (the reference engines are always built).
  if (!plan.referee) throw std::logic_error("plane: the exact referee is not registered");
  std::string md = method_markdown(plan.settings, plan.seed, kReferee, plan.categories) +
                   agreement_section(checks, plan, out_dir, results, res.data, res.stderr_lines, res.views);
  md += contact_section(checks, plan, out_dir, results, res.data);
  md += drop_section(checks, plan, results, res.data);
  res.markdown = md + "\nWhat runs is set in `comparisons/suites/plane/settings.h`; the tolerance file holds the bands only.\n";
  res.checks = checks.finish();
  return res;
}

}  // namespace tecido::suites::plane

namespace tecido::suites {

Sweep plane_sweep_for(const SuiteContext& ctx, plane::Settings settings, std::vector<plane::Category> categories,
                      const std::vector<SegmentPlaneEngine>& engines) {
  auto plan = std::make_shared<const plane::Plan>(plane::make_plan(ctx, std::move(settings), std::move(categories), engines));
  Sweep s;
  s.cases = plane::case_count(plan->layout);
  s.run_case = [plan](std::size_t k) { return plane::run_case(*plan, k); };
  const std::string out_dir = ctx.out_dir;
  s.assemble = [plan, out_dir](const std::vector<io::Json>& results) { return plane::assemble(*plan, out_dir, results); };
  return s;
}

Sweep plane_sweep(const SuiteContext& ctx) {
  return plane_sweep_for(ctx, plane::settings(ctx.quick), plane::categories(), segment_plane_engines());
}

SuiteResult run_plane_suite(const SuiteContext& ctx) { return run_sweep(&plane_sweep, ctx, "plane"); }

}  // namespace tecido::suites
