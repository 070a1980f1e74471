#include "comparisons/suites/tritri/check_plan.h"

#include <algorithm>

namespace tecido::suites::tritri {

CheckScope check_scope(const std::string& engine, const std::string& referee, bool outside) {
  if (outside) return CheckScope::Outside;
  if (engine == "core") return CheckScope::EveryFamily;
  // The seed's two tests (rotation test, Moller-Trumbore on edges with the seed's AND) are kept as
  // the seed wrote them, misses included: the report shows how they fare, nothing requires them to
  // agree. The referee agrees with itself by definition.
  if (engine == "core-rotation" || engine == "core-mt" || engine == referee) return CheckScope::Reported;
  return CheckScope::RandomOnly;
}

bool is_checked(CheckScope scope, const Family& family) {
  switch (scope) {
    case CheckScope::EveryFamily: return true;
    case CheckScope::Outside: return true;
    case CheckScope::RandomOnly: return family.random;
    case CheckScope::Reported: return false;
  }
  return false;
}

std::string check_name(const std::string& engine, const std::string& family) {
  return "tritri/" + engine + "/agreement/" + family;
}

std::string tolerance_key(const std::string& engine, CheckScope scope) {
  return scope == CheckScope::Outside ? "/tritri/outside_min_agreement" : "/tritri/" + engine + "_min_agreement";
}

CheckList declare_checks(const std::vector<Family>& families, const std::vector<std::string>& engines,
                         const std::string& referee, const Tolerances& tol, const std::vector<std::string>& outside) {
  CheckList checks;
  for (const std::string& e : engines) {
    const bool is_outside = std::find(outside.begin(), outside.end(), e) != outside.end();
    const CheckScope scope = check_scope(e, referee, is_outside);
    for (const Family& f : families) {
      if (!is_checked(scope, f)) continue;
      checks.declare(check_name(e, f.name), tol.at_least(tolerance_key(e, scope), 1.0),
                     "share of " + f.name + " pairs where " + e + " agrees with " + referee);
    }
  }
  return checks;
}

}  // namespace tecido::suites::tritri
