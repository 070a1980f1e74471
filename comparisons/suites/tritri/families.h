#pragma once
/// The `tritri` suite's families of triangle pairs: uniform random pairs, and adversarial
/// families built to sit exactly on the cases floating-point tests get wrong (coplanar, touching
/// at a vertex or an edge, sharing a vertex, degenerate slivers, far from the origin).
///
/// Pair k of family f is a pure function of (seed, f, k): its generator draws from its own
/// substream, so any pair can be regenerated alone (a case, the disagreement file) and the
/// pairs do not depend on how they are split into cases.
#include "comparisons/io/tri_pairs.h"
#include "comparisons/suites/agreement/family.h"
#include "comparisons/suites/random.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tecido::suites::tritri {

/// A family (comparisons/suites/agreement/family.h): name, what it claims, the generator of pair k,
/// and whether it is the uniform family (references are checked and speed is measured on it).
using Family = agreement::Family<io::TriPair>;

/// Every family in report order: random first, then the adversarial ones.
const std::vector<Family>& families();

/// Pair k of `family` (index `f` in its table) for `seed`, with id "<name>/<k>".
io::TriPair family_pair(std::uint64_t seed, std::size_t f, const Family& family, long k);

}  // namespace tecido::suites::tritri
