#include "comparisons/suites/plane/check_plan.h"

#include "comparisons/suites/plane/theory.h"

#include <fmt/format.h>

namespace tecido::suites::plane {

const std::vector<CategoryGroup>& category_groups() {
  static const std::vector<CategoryGroup> groups = {
      {"random", {"random"}, TErrorBand::Near},
      {"border", {"edge", "corner"}, TErrorBand::Near},
      {"exact-geometry", {"parallel", "in-plane", "start-on", "end-on"}, TErrorBand::Near},
      {"grazing", {"grazing"}, TErrorBand::None},
      {"far", {"far"}, TErrorBand::Far},
  };
  return groups;
}

const CategoryGroup* group_of(const std::string& category) {
  for (const CategoryGroup& g : category_groups())
    for (const std::string& m : g.categories)
      if (m == category) return &g;
  return nullptr;
}

CheckScope check_scope(const std::string& engine, const std::string& referee) {
  if (engine == "core") return CheckScope::Exact;
  if (engine == referee || engine.rfind("core-", 0) == 0) return CheckScope::Reported;
  return CheckScope::Reference;
}

std::string agreement_check(const std::string& engine, const std::string& group) {
  return "plane/" + engine + "/agreement/" + group;
}

std::string t_error_check(const std::string& engine, const std::string& group) {
  return "plane/" + engine + "/t_error/" + group;
}

std::string contact_time_check(IntegratorKind k, double h) {
  return fmt::format("plane/contact_time/{}/h={}", integrator_name(k), h);
}

namespace {

void declare_agreement(CheckList& checks, const std::string& e, const std::string& referee, const Tolerances& tol) {
  for (const CategoryGroup& g : category_groups()) {
    checks.declare(agreement_check(e, g.name), tol.at_least("/plane/" + e + "_agreement_" + g.name, 1.0),
                   "share of " + g.name + " cases where " + e + "'s hit equals " + referee + "'s");
    if (g.t_error == TErrorBand::None) continue;
    const char* band = g.t_error == TErrorBand::Far ? "far" : "near";
    checks.declare(t_error_check(e, g.name), tol.at_most("/plane/" + e + "_t_error_" + band),
                   "max |t - t_" + referee + "| over " + g.name + " cases where both hit");
  }
}

}  // namespace

CheckList declare_checks(const Settings& s, const std::vector<std::string>& engines, const std::string& referee,
                         bool with_bullet, const Tolerances& tol) {
  CheckList checks;
  if (!referee.empty())
    for (const std::string& e : engines)
      if (check_scope(e, referee) != CheckScope::Reported) declare_agreement(checks, e, referee, tol);
  for (IntegratorKind k : s.contact_time.integrators) {
    if (!exact_for_constant_acceleration(k)) continue;
    for (double h : s.contact_time.steps)
      checks.declare(contact_time_check(k, h), tol.at_most("/plane/contact_time_over_tolerance"),
                     "max over levels and drops of |t_contact - t_analytic| / bisection tolerance");
  }
  checks.declare(kCoreApexCheck, tol.at_most("/plane/drop_core_apex_rel"),
                 "max over heights of |apex - k^2 z0| / (k^2 z0), core (midpoint)");
  if (with_bullet)
    checks.declare(kBulletContactCheck, tol.at_most("/plane/drop_bullet_contact_time_error_steps", s.drop.dt),
                   "max over heights of |t_contact - sqrt(2 z0 / g)| [s], Bullet's rigid sphere");
  return checks;
}

}  // namespace tecido::suites::plane
