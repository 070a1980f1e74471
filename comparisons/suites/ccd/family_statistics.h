#pragma once
/// What the ccd suite measures per family: the referee's counts and, per engine, false negatives
/// and positives against the exact referee, the time-of-impact error where both hit, and the
/// time per query. Carried between a case and the assembly as JSON (lossless).
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/agreement/tally.h"

#include <string>
#include <vector>

namespace tecido::suites::ccd {

/// One engine on one family, against the exact referee: the agreement kit's tally
/// (comparisons/suites/agreement/tally.h: misses are the false negatives, false hits the false
/// positives, no answer counted neither way, max_t_error the largest |toi - t*| where both hit),
/// and what only continuous collision measures.
struct EngineTally {
  std::string engine;
  agreement::Tally tally;
  double sum_toi_error = 0.0;  ///< |toi - t*| summed over tally.both_hit
  long toi_after = 0;  ///< both hit and toi is certainly later than the referee's t*
  /// The largest toi - t* where both hit, t* the referee's toi (0 when never later): how late the
  /// engine says a contact begins; a late toi lets a simulation tunnel as a miss does.
  double max_toi_late = 0.0;
  double seconds = 0.0;  ///< wall time answering the family's queries (one thread, this run)

  double ns_per_query() const { return tally.cases ? 1e9 * seconds / static_cast<double>(tally.cases) : 0.0; }
  double mean_toi_error() const { return tally.both_hit ? sum_toi_error / static_cast<double>(tally.both_hit) : 0.0; }
};

/// The referee's counts and every engine's tally on one family.
struct FamilyResult {
  std::string family;
  long queries = 0;
  long contacts = 0;             ///< referee's hits
  long known = 0;                ///< queries with a constructed answer
  long known_mismatch = 0;       ///< ... where the referee differs from it (hit, or toi when hit)
  long unfiltered = 0;           ///< queries also answered without the referee's filter
  long unfiltered_mismatch = 0;  ///< ... with a different answer
  std::vector<EngineTally> engines;
  /// Each disagreement with the referee, at most the settings' cap: the engine's index into the
  /// suite's engines (suite_engines.h), k the query's index in the family, both answers (t: toi).
  std::vector<agreement::Disagreement> disagree;

  /// Share of the referee's contacts an engine missed, and of its misses it called hits.
  double fn_rate(const EngineTally& e) const { return contacts ? static_cast<double>(e.tally.misses) / contacts : 0.0; }
  double fp_rate(const EngineTally& e) const {
    return queries > contacts ? static_cast<double>(e.tally.false_hits) / static_cast<double>(queries - contacts) : 0.0;
  }
};

io::Json family_result_json(const FamilyResult& r);
FamilyResult family_result_from_json(const io::Json& j);

}  // namespace tecido::suites::ccd
