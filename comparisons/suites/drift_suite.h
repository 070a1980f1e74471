#pragma once
/// Suite `drift`: (a) energy and momentum over long runs (10^5 steps) per integrator on
/// conservative scenes; (b) core versus Bullet on identical cloth scenes (when the Bullet
/// adapters are built).
#include "comparisons/suites/suite.h"

namespace tecido::suites {

SuiteResult run_drift_suite(const SuiteContext& ctx);

}  // namespace tecido::suites
