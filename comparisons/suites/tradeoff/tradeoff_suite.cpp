#include "comparisons/suites/tradeoff/tradeoff_suite.h"

#include "comparisons/suites/tradeoff/cases.h"
#include "comparisons/suites/tradeoff/curtain.h"
#include "comparisons/suites/tradeoff/findings.h"
#include "comparisons/suites/tradeoff/outside_engines.h"
#include "comparisons/suites/tradeoff/points.h"
#include "comparisons/suites/tradeoff/size_analysis.h"
#include "comparisons/suites/tradeoff/theory.h"
#include "comparisons/suites/tradeoff/tradeoff_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace tecido::suites {

namespace tradeoff {

namespace {

const char* const kTwin = "bullet-deformable";
const char* const kCoreTwin = "core-symplectic";

bool has_engine(const std::vector<TradeoffEngine>& engines, const std::string& name) {
  return std::any_of(engines.begin(), engines.end(), [&](const TradeoffEngine& e) { return e.name == name; });
}

std::string twin_check(int n) { return fmt::format("tradeoff/{}/{}_vs_{}", n, kTwin, kCoreTwin); }

/// Whether the twin check exists on the n x n cloth: both engines run there.
bool twin_checked(const std::vector<TradeoffEngine>& engines, int n) {
  for (const TradeoffEngine& e : engines)
    if (e.name == kTwin) return has_engine(engines, kCoreTwin) && !skipped(e, n, 0);
  return false;
}

}  // namespace

CheckList declare_tradeoff_checks(const Settings& s, const std::vector<TradeoffEngine>& engines, const Tolerances& tol) {
  CheckList c;
  for (const Size& z : s.sizes) {
    const std::string p = fmt::format("tradeoff/{}/", z.n);
    std::size_t points = 0;
    for (const TradeoffEngine& e : engines)
      for (std::size_t j = 0; j < static_cast<std::size_t>(z.steps); ++j) points += skipped(e, z.n, j) ? 0 : 1;
    c.declare(p + "conditioning", tol.at_most("/tradeoff/conditioning_max"),
              "RMS change at the end per metre of in-plane nudge at t = 0");
    c.declare(p + "reference_error", tol.at_most("/tradeoff/reference_max_error"),
              "estimated RMS error of the reference: RMS(RK4(2 h_ref) - RK4(h_ref)) / 15 [m]");
    c.declare(p + "reference_order", tol.between("/tradeoff/reference_order_lo", "/tradeoff/reference_order_hi"),
              "observed order of RK4 at h_min and h_min / 2, against the reference at h_min / 4");
    c.declare(p + "front_size", tol.at_least("/tradeoff/front_min_points", static_cast<double>(points)),
              "points on the Pareto front (at most the points run); none when no run counted");
    if (twin_checked(engines, z.n))
      c.declare(twin_check(z.n), tol.at_most("/tradeoff/twin_max_rms_difference"),
                "max RMS distance between bullet-deformable's and core-symplectic's final positions at equal steps [m]");
  }
  return c;
}

}  // namespace tradeoff

namespace {

using namespace tradeoff;

/// What the cases and the assembly share.
struct Plan {
  SuiteContext ctx;
  Settings settings;
  std::vector<TradeoffEngine> engines;
  std::vector<Scene> scenes;               ///< hanging_cloth(n) per size
  std::vector<std::vector<double>> swept;  ///< per size
  CaseLayout layout;
  CheckList checks;  ///< declared before any case runs
};

io::Json run_case(const Plan& plan, std::size_t k) {
  const CaseIndex c = plan.layout.locate(k);
  const int n = plan.settings.sizes[c.size].n;
  const Scene& scene = plan.scenes[c.size];
  const std::vector<double>& hs = plan.swept[c.size];
  if (!c.timed) return untimed_case(c.untimed, scene, hs, plan.settings, plan.ctx.seed, n);
  return point_case(plan.engines[c.engine], scene, n, c.step, hs[c.step], plan.settings);
}

/// One size's measurements from its case results.
SizeAnalysis analyse(const Plan& plan, std::size_t si, const std::vector<io::Json>& results) {
  SizeAnalysis a;
  a.n = plan.settings.sizes[si].n;
  a.springs = plan.scenes[si].forces.springs.size();
  a.omega = omega_bound(plan.scenes[si]);
  a.swept = plan.swept[si];
  std::vector<std::optional<std::vector<Vec3>>> untimed;
  std::string reference_reason;
  for (std::size_t u = 0; u < kUntimed; ++u) {
    const io::Json& r = results.at(plan.layout.untimed_case(si, static_cast<Untimed>(u)));
    const std::string* err = case_error(r);
    untimed.push_back(err ? std::nullopt : positions_of(r));
    if (u == 0) reference_reason = err ? *err : r.at("reason").get<std::string>();
  }
  a.points = size_points(plan.layout, si, a.swept, plan.engines, results, untimed[0], plan.settings);
  const Point* rk4 = point_at(a, plan.engines, "core-rk4", a.swept.size() - 1);
  a.reference = estimate_reference(untimed, reference_reason, rk4 ? rk4->error : NAN,
                                   reference_step(a.swept, plan.settings), plan.settings);
  a.front = front_of(a.points);
  return a;
}

/// Sets `name`, or fails it with `why` when the value is not finite.
void set_or_fail(CheckList& checks, const std::string& name, double value, const std::string& why) {
  if (std::isfinite(value)) return checks.set(name, value);
  checks.fail(name, why);
}

void record(CheckList& checks, const Plan& plan, const SizeAnalysis& a) {
  const std::string p = fmt::format("tradeoff/{}/", a.n);
  const ReferenceEstimate& r = a.reference;
  set_or_fail(checks, p + "conditioning", r.conditioning_in, "a conditioning probe run failed");
  const std::string no_ref = r.failure.empty() ? "the confirmation run failed" : "no reference: " + r.failure;
  set_or_fail(checks, p + "reference_error", r.error, no_ref);
  set_or_fail(checks, p + "reference_order", r.order, r.failure.empty() ? "RK4 at h_min has no error" : no_ref);
  checks.set(p + "front_size", static_cast<double>(a.front.size()));
  if (checks.declared(twin_check(a.n)))
    set_or_fail(checks, twin_check(a.n), engines_distance(a, plan.engines, kTwin, kCoreTwin),
                "no step at which both returned positions");
  for (int i : a.front) {
    const Point& pt = a.points[i];
    const std::string name = fmt::format("{}front/{}@{}/reproducible", p, plan.engines[pt.engine].name, h_label(pt.h));
    checks.declare(name, plan.ctx.tolerances->at_most("/tradeoff/reproducible_max_abs_diff"),
                   "rerun: max |x - x_rerun| over nodes [m], bit-identical = 0");
    checks.set(name, pt.rerun_diff);
  }
  record_outside_checks(checks, a, plan.engines);
}

SuiteResult assemble(const Plan& plan, const std::vector<io::Json>& results) {
  SuiteResult res;
  res.name = "tradeoff";
  CheckList checks = plan.checks;
  std::string md = method_markdown(plan.settings) + outside_markdown(plan.engines);
  std::vector<SizeAnalysis> sizes;
  for (std::size_t si = 0; si < plan.settings.sizes.size(); ++si) {
    sizes.push_back(analyse(plan, si, results));
    const SizeAnalysis& a = sizes.back();
    record(checks, plan, a);
    md += size_markdown(a, plan.engines) + size_plot(plan.ctx, a, plan.engines, res.plots) + "\n";
    res.data[fmt::format("cloth{}", a.n)] = size_json(a, plan.engines);
  }
  res.markdown = md + fronts_markdown(sizes, plan.engines) + core_findings(sizes, plan.engines) +
                 bullet_findings(sizes, plan.engines, plan.settings);
  res.checks = checks.finish();
  return res;
}

}  // namespace

Sweep tradeoff_sweep(const SuiteContext& ctx) {
  auto plan = std::make_shared<Plan>();
  plan->ctx = ctx;
  plan->settings = settings(ctx.quick);
  plan->engines = tradeoff_engines(plan->settings, &ctx);
  for (const Size& z : plan->settings.sizes) {
    plan->scenes.push_back(hanging_cloth(z.n));
    plan->swept.push_back(swept_steps(plan->scenes.back(), z.steps));
  }
  plan->layout = case_layout(plan->settings.sizes, plan->engines.size());
  plan->checks = declare_tradeoff_checks(plan->settings, plan->engines, *ctx.tolerances);
  declare_outside_checks(plan->checks, plan->settings, plan->engines, *ctx.tolerances);
  Sweep s;
  s.cases = plan->layout.cases;
  s.run_case = [plan](std::size_t k) { return run_case(*plan, k); };
  s.assemble = [plan](const std::vector<io::Json>& results) { return assemble(*plan, results); };
  return s;
}

SuiteResult run_tradeoff_suite(const SuiteContext& ctx) { return run_sweep(&tradeoff_sweep, ctx, "tradeoff"); }

}  // namespace tecido::suites
