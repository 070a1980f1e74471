#pragma once
/// Agreement statistics of the `plane` suite: how often each engine's hit equals the exact
/// referee's, per category, summed over the cases; the largest crossing-fraction error where both
/// hit; the CPU time each engine spent on the random category; and which cases disagreed.
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/plane/case_index.h"
#include "comparisons/suites/plane/check_plan.h"
#include "core/geometry/segment_plane.h"

#include <optional>
#include <string>
#include <vector>

namespace tecido::suites::plane {

/// One engine on a set of cases.
struct Tally {
  long cases = 0, agree = 0;
  long false_hits = 0, misses = 0;  ///< answered hit where the referee says miss, and the reverse
  long no_answer = 0;               ///< the engine could not answer (neither agrees nor is listed)
  long both_hit = 0;                ///< cases where the engine and the referee both hit
  double max_t_error = 0.0;         ///< max |t - t_referee| over those; meaningless when both_hit == 0
  long exact_path = 0;              ///< calls core's floating-point filter left to its exact path
  void add(const Tally& t);
  /// agree / cases (NaN when there is no case).
  double rate() const;
};

/// The tally of `answers` against `truth` (same length). When `disagree` is given, the index of each
/// answer whose hit differs from the truth's is appended, offset by `first`, up to `cap` entries.
Tally count_agreement(const std::vector<SegmentPlaneHit>& truth, const std::vector<std::optional<SegmentPlaneHit>>& answers,
                      std::vector<long>* disagree = nullptr, long first = 0, std::size_t cap = 0);

/// An engine's disagreement on case k of a category.
struct Disagreement {
  std::size_t engine = 0, category = 0;
  long k = 0;
};

/// Everything the agreement cases measured, summed. Indices: [category][engine] for the tallies.
struct AgreementTable {
  std::vector<std::string> engines;                 ///< in the order of the case results
  std::vector<std::string> error;                   ///< per category: the first error of one of its cases
  std::vector<long> hits;                           ///< per category: cases the referee says hit
  std::vector<std::vector<Tally>> tally;            ///< [category][engine]
  std::vector<double> random_seconds;               ///< per engine: thread CPU time over the random cases
  std::vector<long> random_cases_timed;             ///< per engine: cases those seconds cover
  std::vector<std::vector<Disagreement>> disagree;  ///< per engine, in case order
};

AgreementTable empty_table(std::size_t categories, const std::vector<std::string>& engines);

/// Adds one case's result (agreement_case.h's JSON, or {"error": ...}) for the cases of `range`.
void add_case(AgreementTable& table, const CaseRange& range, const std::vector<Category>& categories,
              const io::Json& result);

/// Nanoseconds per random case of engine e (NaN when no random case was timed).
double ns_per_case(const AgreementTable& table, std::size_t e);

/// A group's tally for engine e, summed over the group's categories present in `categories`, or
/// the reason it has no value: the first error among them ("edge: case 3 threw: ...").
struct GroupTally {
  Tally tally;
  std::string error;
};
GroupTally group_tally(const AgreementTable& table, const std::vector<Category>& categories, const CategoryGroup& group,
                       std::size_t e);

}  // namespace tecido::suites::plane
