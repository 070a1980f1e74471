#pragma once
/// Suite `selfcollision`: on frames recorded from the seed's experiment scene and from a cloth
/// crumpling onto a plane, the intersecting triangle-pair sets of every self-collision engine
/// (core broad + narrow phase, core brute force, FCL's BVH, exact brute force) against the
/// exact referee: precision and recall per engine, and time per frame.
#include "comparisons/suites/suite.h"

#include <array>
#include <vector>

namespace tecido::suites {

/// Pair-set agreement of `got` with `truth` (both sorted, no duplicates).
struct PairAgreement {
  long reported = 0, true_positives = 0, false_positives = 0, missed = 0;
  void add(const std::vector<std::array<int, 2>>& got, const std::vector<std::array<int, 2>>& truth);
  /// reported pairs that are true / reported (1 when nothing was reported).
  double precision() const { return reported ? double(true_positives) / double(reported) : 1.0; }
  /// true pairs reported / true pairs (1 when there were none).
  double recall() const { return (true_positives + missed) ? double(true_positives) / double(true_positives + missed) : 1.0; }
};

SuiteResult run_selfcollision_suite(const SuiteContext& ctx);

}  // namespace tecido::suites
