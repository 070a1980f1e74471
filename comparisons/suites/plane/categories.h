#pragma once
/// The `plane` suite's categories of segment-versus-bounded-plane cases: uniform random cases and
/// adversarial ones built to sit exactly where a floating-point test decides by rounding (a
/// crossing on the rectangle's edge or corner, a segment grazing the plane, parallel to it, lying
/// in it, starting or ending on it, far from the origin).
///
/// Case k of category c is a pure function of (seed, c, k): each case draws from its own
/// substream, so any case can be regenerated alone (a sweep case, the disagreement file) and the
/// cases do not depend on how they are cut into blocks.
#include "comparisons/io/plane_cases.h"
#include "comparisons/suites/agreement/family.h"
#include "comparisons/suites/random.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tecido::suites::plane {

/// A category (comparisons/suites/agreement/family.h): name, what it claims, the generator of case
/// k, and whether it is the uniform one (its count is Settings::random_cases; speed is timed on it).
using Category = agreement::Family<io::PlaneCase>;

/// Every category in report order: random first, then the adversarial ones.
const std::vector<Category>& categories();

/// Case k of `category` (index `c` in its table) for `seed`, with id "<name>/<k>".
io::PlaneCase category_case(std::uint64_t seed, std::size_t c, const Category& category, long k);

/// The category part of a case id ("edge/12" -> "edge").
std::string case_category(const std::string& id);

}  // namespace tecido::suites::plane
