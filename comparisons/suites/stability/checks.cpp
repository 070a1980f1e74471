#include "comparisons/suites/stability/checks.h"

#include <fmt/format.h>

namespace tecido::suites::stability {

std::string check_name(IntegratorKind k, const std::string& what) {
  return fmt::format("stability/{}/{}", integrator_name(k), what);
}

CheckList declare_checks(const Settings& s, const std::vector<ExtremeGroup>& groups, const Tolerances& tol) {
  CheckList checks;
  const Band ratio = tol.between("/stability/ratio_lo", "/stability/ratio_hi");
  for (IntegratorKind k : s.bounded) {
    checks.declare(check_name(k, "h_omega_ratio_min"), ratio, "min over the grid of measured h_max omega / theory");
    checks.declare(check_name(k, "h_omega_ratio_max"), ratio, "max over the grid of measured h_max omega / theory");
    checks.declare(check_name(k, "grid_spread"), tol.at_most("/stability/grid_spread"),
                   "h_max omega depends on h omega only: max/min - 1 over the grid");
  }
  for (IntegratorKind k : s.growers)
    checks.declare(check_name(k, "growth_rel_error"), tol.at_most("/stability/growth_rel_error"),
                   "measured log growth per period vs theory, worst over grid and c");
  const Band horizon = tol.between("/stability/horizon_ratio_lo", "/stability/horizon_ratio_hi");
  for (IntegratorKind k : s.growers) {
    checks.declare(check_name(k, "horizon_ratio_min"), horizon, "horizon-limited step, measured / predicted");
    checks.declare(check_name(k, "horizon_ratio_max"), horizon, "horizon-limited step, measured / predicted");
  }
  for (const ExtremeGroup& g : groups)
    for (const CheckSpec& c : g.checks(s)) checks.declare(c.name, c.band(tol), c.note);
  return checks;
}

}  // namespace tecido::suites::stability
