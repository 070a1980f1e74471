#pragma once
/// Suite `tritri`: every triangle-triangle engine against the exact referee on random pairs and
/// adversarial families, by category, with nanoseconds per pair.
#include "comparisons/io/tri_pairs.h"
#include "comparisons/suites/suite.h"
#include "comparisons/suites/sweep.h"

namespace tecido::suites {

/// Deterministic pairs from `seed`: `n_random` in the unit cube and `n_per_category` of each
/// adversarial family. Ids "<category>/<k>"; categories: random, near-coplanar, coplanar,
/// touch-vertex, touch-edge, shared-vertex, sliver, offset.
std::vector<io::TriPair> make_tri_pairs(std::uint64_t seed, int n_random, int n_per_category);

/// The suite as a sweep (comparisons/suites/sweep.h): case k runs the referee and every engine on
/// the k-th block of 10000 pairs; assembly sums the tallies and timings.
Sweep tritri_sweep(const SuiteContext& ctx);
SuiteResult run_tritri_suite(const SuiteContext& ctx);

}  // namespace tecido::suites
