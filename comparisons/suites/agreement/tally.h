#pragma once
/// One engine against the exact referee on a set of cases: the answers compared hit for hit, the
/// time (crossing fraction, time of impact) compared where both hit, and each disagreement recorded
/// with both answers.
#include <cstddef>
#include <optional>
#include <vector>

namespace tecido::suites::agreement {

/// An answer to one case: hit or not, and where along the motion (0 when the test has no time).
struct Answer {
  bool hit = false;
  double t = 0.0;
};

/// An engine's answer that differs from the referee's (a false hit or a miss) on case k of a family.
struct Disagreement {
  std::size_t engine = 0, family = 0;
  long k = 0;
  Answer answer;  ///< the engine's
  Answer truth;   ///< the referee's
};

struct Tally {
  long cases = 0, agree = 0;
  long false_hits = 0, misses = 0;  ///< answered hit where the referee says miss, and the reverse
  long no_answer = 0;               ///< the engine could not answer (neither agrees nor is listed)
  long both_hit = 0;                ///< cases where the engine and the referee both hit
  double max_t_error = 0.0;         ///< max |t - t_referee| over those; meaningless when both_hit == 0
  long exact_path = 0;              ///< calls the engine's floating-point filter left to its exact path (where counted)
  void add(const Tally& t);
  /// agree / cases: the share of cases on which the engine agrees (NaN when there is no case).
  double rate() const;
  /// false_hits + misses.
  long disagreements() const { return false_hits + misses; }
};

/// The tally of `answers` against `truth` (same length; std::invalid_argument otherwise). When
/// `disagree` is given, each answer whose hit differs from the truth's is appended (k offset by
/// `first`; engine and family left 0), up to `cap` entries.
Tally count_agreement(const std::vector<Answer>& truth, const std::vector<std::optional<Answer>>& answers,
                      std::vector<Disagreement>* disagree = nullptr, long first = 0, std::size_t cap = 0);

}  // namespace tecido::suites::agreement
