#pragma once
/// How a set of reported triangle pairs compares with the true set: precision and recall, and
/// which pairs differ.
#include <array>
#include <vector>

namespace tecido::suites::selfcollision {

/// The pairs of a frame an engine got wrong: the true pairs it did not report and the pairs it
/// reported that are not true, each sorted.
struct PairDifference {
  std::vector<std::array<int, 2>> missed, extra;
};

/// `got` against `truth` (both sorted, without duplicates).
PairDifference pair_difference(const std::vector<std::array<int, 2>>& got, const std::vector<std::array<int, 2>>& truth);

/// Pair-set agreement summed over frames.
struct PairAgreement {
  long reported = 0, true_positives = 0, false_positives = 0, missed = 0;
  /// Adds one frame: `got` and `truth` sorted, without duplicates.
  void add(const std::vector<std::array<int, 2>>& got, const std::vector<std::array<int, 2>>& truth);
  /// Reported pairs that are true / reported pairs (1 when nothing was reported).
  double precision() const { return reported ? double(true_positives) / double(reported) : 1.0; }
  /// True pairs reported / true pairs (1 when there were none).
  double recall() const {
    return (true_positives + missed) ? double(true_positives) / double(true_positives + missed) : 1.0;
  }
};

}  // namespace tecido::suites::selfcollision
