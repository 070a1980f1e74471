#pragma once
/// What the ccd suite measures per family: the referee's counts and, per engine, false negatives
/// and positives against the exact referee, the time-of-impact error where both hit, and the
/// time per query. Carried between a case and the assembly as JSON (lossless).
#include "comparisons/io/json_reader.h"

#include <string>
#include <vector>

namespace tecido::suites::ccd {

/// One engine on one family, against the exact referee.
struct EngineTally {
  std::string engine;
  long queries = 0;    ///< queries of the family
  long no_answer = 0;  ///< the engine could not answer (null): counted neither way
  long fn = 0;         ///< missed contacts
  long fp = 0;         ///< hits where the referee says miss
  long both_hit = 0;   ///< queries where both hit (the time-of-impact error is measured on these)
  double max_toi_error = 0.0, sum_toi_error = 0.0;  ///< |toi - t*| over both_hit
  long toi_after = 0;  ///< both hit and toi is certainly later than the referee's t*
  double seconds = 0.0;  ///< wall time answering the family's queries (one thread, this run)

  double ns_per_query() const { return queries ? 1e9 * seconds / static_cast<double>(queries) : 0.0; }
  double mean_toi_error() const { return both_hit ? sum_toi_error / static_cast<double>(both_hit) : 0.0; }
};

/// An engine's answer that differs from the referee's on one query of the family.
struct Disagreement {
  int engine = 0;   ///< index into the suite's engines (suite_engines.h)
  long query = 0;   ///< index into the family's queries
  bool truth = false;  ///< the referee's hit
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
  /// Each disagreement with the referee, at most the settings' cap.
  std::vector<Disagreement> disagree;

  /// Share of the referee's contacts an engine missed, and of its misses it called hits.
  double fn_rate(const EngineTally& e) const { return contacts ? static_cast<double>(e.fn) / contacts : 0.0; }
  double fp_rate(const EngineTally& e) const {
    return queries > contacts ? static_cast<double>(e.fp) / static_cast<double>(queries - contacts) : 0.0;
  }
};

io::Json family_result_json(const FamilyResult& r);
FamilyResult family_result_from_json(const io::Json& j);

}  // namespace tecido::suites::ccd
