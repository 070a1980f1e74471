#pragma once
/// One case of the ccd suite: a family's block of queries through the exact referee and every
/// registered continuous collision engine (comparisons/engines/ccd_engines.h), tallied.
#include "comparisons/suites/ccd/constructions.h"
#include "comparisons/suites/ccd/family_statistics.h"
#include "comparisons/suites/ccd/settings.h"

#include <string>
#include <vector>

namespace tecido::suites::ccd {

/// The referee (reference::exact_ccd) on every query: the truth, checked against each
/// constructed answer and, on the first settings.unfiltered_per_family queries, against the
/// referee without its filter. Then every engine on every query, timed over the block (one
/// thread), each answer compared with the truth. Needs the reference build (the referee).
FamilyResult run_family(const std::string& family, const std::vector<KnownQuery>& queries, const Settings& s);

}  // namespace tecido::suites::ccd
