#pragma once
/// One case of the ccd suite: a family's block of queries through the exact referee and every
/// engine the suite runs (suite_engines.h: built-in and outside), tallied.
#include "comparisons/suites/ccd/constructions.h"
#include "comparisons/suites/ccd/family_statistics.h"
#include "comparisons/suites/ccd/settings.h"
#include "comparisons/suites/ccd/suite_engines.h"

#include <string>
#include <vector>

namespace tecido::suites::ccd {

/// The referee (reference::exact_ccd) on every query: the truth, checked against each
/// constructed answer and, on the first settings.unfiltered_per_family queries, against the
/// referee without its filter. Then every engine of `engines` on every query, timed over the
/// block (one thread; an outside engine gets the block in one batch), each answer compared with
/// the truth; disagreements name engines by their index in `engines`. Needs the reference build.
FamilyResult run_family(const std::string& family, const std::vector<KnownQuery>& queries, const Settings& s,
                        const std::vector<SuiteEngine>& engines);

}  // namespace tecido::suites::ccd
