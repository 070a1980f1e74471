#include "comparisons/suites/drift_suite.h"
#include "comparisons/suites/order_suite.h"
#include "comparisons/suites/plane_suite.h"
#include "comparisons/suites/suite.h"

namespace tecido::suites {

const std::vector<SuiteEntry>& suite_registry() {
  static const std::vector<SuiteEntry> suites = {
      {"order", "observed error order of each integrator on analytic problems", &run_order_suite},
      {"drift", "energy and momentum over long runs; core vs Bullet on identical cloth", &run_drift_suite},
      {"plane", "segment vs bounded plane agreement with the exact referee; bisected contact time", &run_plane_suite},
  };
  return suites;
}

}  // namespace tecido::suites
