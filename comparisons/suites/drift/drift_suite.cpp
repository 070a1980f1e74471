#include "comparisons/suites/drift/drift_suite.h"

#include "comparisons/engines/dynamics_engines.h"
#include "comparisons/suites/drift/bullet_cases.h"
#include "comparisons/suites/drift/drift_report.h"
#include "comparisons/suites/drift/invariants.h"
#include "comparisons/suites/drift/outside_drift.h"
#include "comparisons/suites/drift/scenes.h"
#include "comparisons/suites/drift/theory.h"

#include <fmt/format.h>

#include <cmath>
#include <memory>

namespace tecido::suites {

namespace drift {

namespace {

std::string run_prefix(const std::string& scene, IntegratorKind k) {
  return fmt::format("drift/{}/{}/", scene, integrator_name(k));
}

void declare_invariants(CheckList& c, const std::string& scene, IntegratorKind k, const Tolerances& tol) {
  const std::string p = run_prefix(scene, k);
  c.declare(p + "momentum", tol.at_most("/drift/momentum_rel"),
            "max |P(t) - P0| / max(sum m|v0|, sum m|v(t)|)");
  c.declare(p + "angular_momentum", tol.at_most("/drift/angular_momentum_rel"),
            conserves_angular_momentum(k) ? "max |L(t) - L0| / max(sum m|x0||v0|, sum m|x(t)||v(t)|): conserved"
                                          : "max |L(t) - L0 - Cooper's predicted change| / max(sum m|x0||v0|, sum m|x(t)||v(t)|)");
  if (k == IntegratorKind::Symplectic) {
    c.declare(p + "energy_last_over_first_half", tol.at_most("/drift/symplectic_halves_max"),
              "largest energy error of the second half / of the first: bounded");
    c.declare(p + "energy_max_rel", tol.at_most("/drift/symplectic_energy_rel_max"), "max |E(t) - E0| / E0");
  }
  if (k == IntegratorKind::Euler)
    c.declare(p + "energy_last_over_first_half", tol.at_least("/drift/euler_halves_min"),
              "largest energy error of the second half / of the first: grows");
}

void declare_bullet(CheckList& c, const Settings& s, const Tolerances& tol) {
  c.declare("drift/twin/rms_first_second", tol.at_most("/drift/twin_rms_first_second"),
            "max RMS node distance, core symplectic vs Bullet's deformable twin, over the first second [m]");
  c.declare("drift/twin/time_to_1e-6", tol.at_least("/drift/twin_min_time_to_1e-6", s.twin_seconds),
            "first time the RMS distance exceeds 1e-6 m [s]; the run length when it never does");
  c.declare("drift/falling/core_contact_time_error", tol.at_most("/drift/core_contact_time_error_steps", s.twin_dt),
            "|t_core - sqrt(2 z0 / g)| [s]");
  c.declare("drift/falling/twin_contact_time_error", tol.at_most("/drift/twin_contact_time_error_steps", s.twin_dt),
            "|t_twin - sqrt(2 (z0 - margin) / g)| [s]");
  c.declare("drift/falling/core_rest_height", tol.at_most("/drift/core_rest_height"), "max |z| after the fall [m]");
  c.declare("drift/classic/calibrator/sag_rel_error", tol.at_most("/drift/classic_calibrator_rel"),
            "the calibrator's own stopping rule: |sag_bullet - sag_core| / sag_core where it calibrated");
  c.declare(fmt::format("drift/classic/load_x{:g}/sag_ratio", s.classic_load_factor),
            tol.around("/drift/classic_load_sag_ratio", classic_sag_ratio(s.classic_load_factor)),
            "sag_bullet / sag_core at another load; a load-independent model gives 1 / load factor");
  c.declare(fmt::format("drift/classic/load_x{:g}/bullet_shape_change", s.classic_load_factor),
            tol.at_most("/drift/classic_load_shape_change"),
            "max |x_bullet(load) - x_bullet(calibration load)| of the settled shapes [m]");
}

}  // namespace

std::vector<DriftCase> drift_cases(const Settings& s, std::uint64_t seed) {
  std::vector<DriftCase> out;
  for (const Conservative& c : conservative_scenes(seed))
    for (IntegratorKind k : engines::core_integrators())
      out.push_back({c.name + "/" + integrator_name(k), [c, k, s] { return invariant_json(run_invariants(c.scene, k, s)); }});
  out.push_back({"twin", [s] { return twin_case(s); }});
  out.push_back({"falling", [s] { return falling_case(s); }});
  out.push_back({"classic", [s] { return classic_case(s); }});
  out.push_back({"wind", [s] { return wind_case(s); }});
  return out;
}

CheckList declare_drift_checks(const Settings& s, std::uint64_t seed, const Tolerances& tol) {
  CheckList c;
  for (const Conservative& sc : conservative_scenes(seed))
    for (IntegratorKind k : engines::core_integrators()) declare_invariants(c, sc.name, k, tol);
  declare_bullet(c, s, tol);
  return c;
}

}  // namespace drift

namespace {

using drift::InvariantRow;

/// Sets or fails one run's checks.
void record_invariants(CheckList& checks, const InvariantRow& r) {
  const std::string p = drift::run_prefix(r.scene, r.kind);
  if (!r.error.empty()) return checks.fail_pending(p, r.error);
  if (r.run.unstable_at_step) return checks.fail_pending(p, fmt::format("unstable at step {}", r.run.unstable_at_step));
  checks.set(p + "momentum", r.run.momentum_error);
  checks.set(p + "angular_momentum", r.run.angular_momentum_vs_theory);
  if (checks.declared(p + "energy_last_over_first_half")) checks.set(p + "energy_last_over_first_half", r.run.last_over_first_half);
  if (checks.declared(p + "energy_max_rel")) checks.set(p + "energy_max_rel", r.run.max_rel_energy);
}

/// The reason a Bullet group's checks fail without values, or "" when it produced them.
std::string group_failure(const io::Json& result) {
  if (const std::string* err = case_error(result)) return *err;
  if (result.contains("unstable") && !result.at("unstable").is_null())
    return fmt::format("unstable at step {} ({})", result["unstable"]["step"].get<long long>(),
                       result["unstable"]["engine"].get<std::string>());
  return "";
}

/// Sets `name` to |t - t_exact|, or fails it when the contact never happened.
void record_contact(CheckList& checks, const std::string& name, double t, double t_exact, double seconds) {
  if (std::isnan(t)) return checks.fail(name, fmt::format("no contact within {:g} s", seconds));
  checks.set(name, std::abs(t - t_exact));
}

void record_bullet(CheckList& checks, const drift::Settings& s, const io::Json& twin, const io::Json& falling,
                   const io::Json& classic) {
  if (const std::string why = group_failure(twin); !why.empty()) {
    checks.fail_pending("drift/twin/", why);
  } else {
    checks.set("drift/twin/rms_first_second", get_num(twin.at("rms_window")));
    const double t = get_num(twin.at("crossings").at(1));  // twin_thresholds[1] = 1e-6 m
    checks.set("drift/twin/time_to_1e-6", std::isnan(t) ? s.twin_seconds : t);
  }
  if (const std::string why = group_failure(falling); !why.empty()) {
    checks.fail_pending("drift/falling/", why);
  } else {
    record_contact(checks, "drift/falling/core_contact_time_error", get_num(falling.at("t_core")),
                   get_num(falling.at("t_exact")), s.fall_seconds);
    record_contact(checks, "drift/falling/twin_contact_time_error", get_num(falling.at("t_twin")),
                   get_num(falling.at("t_exact_margin")), s.fall_seconds);
    checks.set("drift/falling/core_rest_height", get_num(falling.at("z_core")));
  }
  if (const std::string why = group_failure(classic); !why.empty()) return checks.fail_pending("drift/classic/", why);
  const std::string load = fmt::format("drift/classic/load_x{:g}/", s.classic_load_factor);
  checks.set("drift/classic/calibrator/sag_rel_error", get_num(classic.at("calibration").at("relative_error")));
  checks.set(load + "sag_ratio", get_num(classic.at("load").at("sag_ratio")));
  checks.set(load + "bullet_shape_change", get_num(classic.at("load").at("bullet_shape_change")));
}

struct Plan {
  drift::Settings settings;
  std::vector<drift::Conservative> scenes;
  std::vector<drift::DriftCase> cases;
  std::vector<outside::OutsideEnginePtr> outside;  ///< their cases follow `cases` (outside_drift.h)
  CheckList checks;  ///< declared before any case runs
};

/// The invariants part of the report, and its checks.
std::string assemble_invariants(const Plan& plan, const SuiteContext& ctx, const std::vector<io::Json>& results,
                                CheckList& checks, SuiteResult& res) {
  std::vector<InvariantRow> rows;
  std::size_t k = 0;
  for (const drift::Conservative& c : plan.scenes) {
    for (IntegratorKind kind : engines::core_integrators()) {
      InvariantRow row{c.name, kind, {}, {}};
      if (const std::string* err = case_error(results.at(k))) row.error = *err;
      else row.run = drift::invariant_from_json(results.at(k));
      io::Json d = results.at(k);
      if (d.is_object()) d.erase("energy_curve");
      res.data[c.name][integrator_name(kind)] = d;
      record_invariants(checks, row);
      rows.push_back(std::move(row));
      ++k;
    }
  }
  std::string md = drift::invariants_method(plan.settings);
  for (const drift::Conservative& c : plan.scenes) md += "- " + c.name + ": " + c.about + ".\n";
  md += "\n" + drift::invariants_table(rows);
  for (const drift::Conservative& c : plan.scenes) md += drift::energy_plot(ctx, c.name, rows, res.plots);
  return md + drift::invariants_findings(rows);
}

SuiteResult assemble(const Plan& plan, const SuiteContext& ctx, const std::vector<io::Json>& results) {
  SuiteResult res;
  res.name = "drift";
  CheckList checks = plan.checks;
  std::string md = drift::settings_markdown(plan.settings) + assemble_invariants(plan, ctx, results, checks, res);
  const std::vector<io::Json> outside(results.begin() + static_cast<std::ptrdiff_t>(plan.cases.size()), results.end());
  md += drift::outside_drift_markdown(plan.scenes, plan.outside, outside, checks, res.data);
  md += "### (b) Core versus Bullet on identical cloth scenes\n\n";
  const std::size_t b = plan.scenes.size() * engines::core_integrators().size();
  const io::Json &twin = results.at(b), &falling = results.at(b + 1), &classic = results.at(b + 2);
  record_bullet(checks, plan.settings, twin, falling, classic);
  md += drift::twin_markdown(ctx, plan.settings, twin, res.plots) + drift::falling_markdown(plan.settings, falling) +
        drift::classic_markdown(plan.settings, classic) + drift::wind_markdown(results.at(b + 3));
  res.data["falling"] = falling;
  res.data["classic"] = classic;
  res.data["twin"] = twin;
  if (res.data["twin"].is_object()) res.data["twin"].erase("curve");
  res.markdown = md;
  res.checks = checks.finish();
  return res;
}

}  // namespace

Sweep drift_sweep(const SuiteContext& ctx) {
  auto plan = std::make_shared<Plan>();
  plan->settings = drift::settings(ctx.quick);
  plan->scenes = drift::conservative_scenes(ctx.seed);
  plan->cases = drift::drift_cases(plan->settings, ctx.seed);
  plan->checks = drift::declare_drift_checks(plan->settings, ctx.seed, *ctx.tolerances);
  engines::DynamicsSources outside_only;
  outside_only.outside = true;
  for (const engines::DynamicsEntry& e : engines::dynamics_engines(outside_only, ctx.outside.get()))
    if (ctx.selects(e.name)) plan->outside.push_back(e.outside_engine);
  drift::declare_outside_drift(plan->checks, plan->scenes, plan->outside, *ctx.tolerances);
  Sweep s;
  s.cases = plan->cases.size() + plan->outside.size() * plan->scenes.size();
  s.run_case = [plan](std::size_t k) {
    if (k < plan->cases.size()) return plan->cases[k].run();
    const std::size_t o = k - plan->cases.size(), n = plan->scenes.size();
    return drift::invariant_json(
        drift::run_outside_invariants(*plan->outside.at(o / n), plan->scenes.at(o % n).scene, plan->settings));
  };
  const SuiteContext c = ctx;
  s.assemble = [plan, c](const std::vector<io::Json>& results) { return assemble(*plan, c, results); };
  return s;
}

SuiteResult run_drift_suite(const SuiteContext& ctx) { return run_sweep(&drift_sweep, ctx, "drift"); }

}  // namespace tecido::suites
