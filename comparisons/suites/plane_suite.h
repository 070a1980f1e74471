#pragma once
/// Suite `plane`: segment versus bounded plane, statically (random and adversarial cases, every
/// registered engine against the exact referee) and dynamically (ballistic particles dropped on
/// planes: the bisected time of contact against the analytic root, as a function of the step
/// and of the bisection tolerance).
#include "comparisons/io/plane_cases.h"
#include "comparisons/suites/suite.h"

#include <vector>

namespace tecido::suites {

/// Deterministic cases from `seed`: `n_random` random ones and `n_per_category` of each
/// adversarial category. The id is "<category>/<k>"; categories: random, edge, corner,
/// grazing, parallel, in-plane, start-on, end-on, far.
std::vector<io::PlaneCase> make_plane_cases(std::uint64_t seed, int n_random, int n_per_category);

/// The category part of a case id ("edge/12" -> "edge").
std::string case_category(const std::string& id);

SuiteResult run_plane_suite(const SuiteContext& ctx);

}  // namespace tecido::suites
