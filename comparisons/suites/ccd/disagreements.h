#pragma once
/// The ccd suite's disagreement file: every query on which an engine differs from the exact
/// referee, as a queries file `tecido ccd --queries DIR/ccd/disagreements.json` re-runs with every
/// engine (comparisons/io/ccd_queries.h). Ids are "<engine>:<kind>/<family>/<index>" and each
/// entry carries the referee's answer as "truth", so the re-run prints false positives and
/// negatives per engine.
#include "comparisons/io/ccd_queries.h"
#include "comparisons/suites/ccd/constructions.h"
#include "comparisons/suites/ccd/family_statistics.h"

#include <string>
#include <vector>

namespace tecido::suites::ccd {

/// Appends family `family`'s disagreements (its queries as generated) to `out`, at most `cap` in
/// all; `engines` are the names the disagreements' engine indices point into.
void add_disagreements(const std::string& family, const FamilyResult& r, const std::vector<KnownQuery>& queries,
                       const std::vector<std::string>& engines, std::size_t cap, std::vector<io::CcdQueryEntry>& out);

}  // namespace tecido::suites::ccd
