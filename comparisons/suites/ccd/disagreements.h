#pragma once
/// The ccd suite's disagreement file: every query on which an engine differs from the exact
/// referee, as a queries file `tecido ccd --queries DIR/ccd/disagreements.json` re-runs
/// (comparisons/io/ccd_queries.h). Ids are "<engine>:<kind>/<family>/<index>"; each entry carries
/// the referee's hit as "truth", so the re-run prints false positives and negatives per engine,
/// and labels the query reader ignores: "engine", its "answer" and the "referee"'s, each
/// {"hit", "toi"} (agreement/replay.h). `--of-engine NAME` replays one engine's entries.
#include "comparisons/io/ccd_queries.h"
#include "comparisons/suites/agreement/tally.h"
#include "comparisons/suites/ccd/constructions.h"
#include "comparisons/suites/ccd/family_statistics.h"

#include <string>
#include <vector>

namespace tecido::suites::ccd {

/// One disagreement kept for the file: its query entry and both answers (d.engine indexes the
/// suite's engines).
struct KeptDisagreement {
  io::CcdQueryEntry entry;
  agreement::Disagreement d;
};

/// Appends family `family`'s disagreements (its queries as generated) to `out`, at most `cap` in
/// all; `engines` are the names the disagreements' engine indices point into.
void add_disagreements(const std::string& family, const FamilyResult& r, const std::vector<KnownQuery>& queries,
                       const std::vector<std::string>& engines, std::size_t cap, std::vector<KeptDisagreement>& out);

/// The file's document: the entries as a queries file, each labelled (agreement::label_entries,
/// times as "toi").
io::Json disagreements_json(const std::vector<KeptDisagreement>& kept, const std::vector<std::string>& engines);

}  // namespace tecido::suites::ccd
