#pragma once
/// Agreement statistics of the `tritri` suite: how often each engine's answer equals the exact
/// referee's, per family, summed over the cases; the referee's own count of intersecting pairs;
/// the wall time each engine spent on the random family; and which pairs disagreed.
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/tritri/case_index.h"

#include <optional>
#include <string>
#include <vector>

namespace tecido::suites::tritri {

/// One engine on a set of pairs: answers equal to the referee's, pairs, and pairs without an
/// answer (an engine that cannot answer neither agrees nor is listed as disagreeing).
struct Tally {
  long agree = 0, pairs = 0, no_answer = 0;
  void add(const Tally& t);
  /// agree / pairs: the share of pairs on which the engine agrees (NaN when there are no pairs).
  double rate() const;
};

/// The tally of `answers` against `truth` (same length). When `disagree` is given, the index of
/// every answer that differs from the truth is appended, offset by `first`, up to `cap` entries.
Tally count_agreement(const std::vector<char>& truth, const std::vector<std::optional<bool>>& answers,
                      std::vector<long>* disagree = nullptr, long first = 0, std::size_t cap = 0);

/// An engine's disagreement on pair k of a family.
struct Disagreement {
  std::size_t engine = 0, family = 0;
  long k = 0;
};

/// Everything the cases measured, summed. Indices: [family][engine] for the tallies.
struct AgreementTable {
  std::vector<std::string> engines;               ///< engine names, in the order of the case results
  std::vector<std::string> error;                 ///< per family: the first error of one of its cases, "" if none
  std::vector<long> intersecting;                 ///< per family: pairs the referee says intersect
  std::vector<std::vector<Tally>> tally;          ///< [family][engine]
  std::vector<double> random_seconds;             ///< per engine: thread CPU time over the random family's pairs
  std::vector<long> random_pairs_timed;           ///< per engine: pairs those seconds cover
  std::vector<std::vector<Disagreement>> disagree;  ///< per engine, in case order
};

/// An empty table for `families` x `engines`.
AgreementTable empty_table(std::size_t families, const std::vector<std::string>& engines);

/// Adds one case's result (tritri_case.h's JSON, or {"error": ...}) for the pairs of `range`.
void add_case(AgreementTable& table, const CaseRange& range, const std::vector<Family>& families,
              const io::Json& result);

/// Nanoseconds per random pair of engine e (NaN when no random pair was timed).
double ns_per_pair(const AgreementTable& table, std::size_t e);

}  // namespace tecido::suites::tritri
