#include "comparisons/suites/tritri/check_plan.h"

namespace tecido::suites::tritri {

CheckScope check_scope(const std::string& engine, const std::string& referee) {
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
    case CheckScope::RandomOnly: return family.random;
    case CheckScope::Reported: return false;
  }
  return false;
}

std::string check_name(const std::string& engine, const std::string& family) {
  return "tritri/" + engine + "/agreement/" + family;
}

CheckList declare_checks(const std::vector<Family>& families, const std::vector<std::string>& engines,
                         const std::string& referee, const Tolerances& tol) {
  CheckList checks;
  for (const std::string& e : engines) {
    const CheckScope scope = check_scope(e, referee);
    for (const Family& f : families) {
      if (!is_checked(scope, f)) continue;
      checks.declare(check_name(e, f.name), tol.at_least("/tritri/" + e + "_min_agreement", 1.0),
                     "share of " + f.name + " pairs where " + e + " agrees with " + referee);
    }
  }
  return checks;
}

}  // namespace tecido::suites::tritri
