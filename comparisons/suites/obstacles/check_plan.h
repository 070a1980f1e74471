#pragma once
/// The `obstacles` suite's checks: declared from the settings and the tolerance file before any
/// case runs (check.h), then fed from each case's result. Names: "obstacles/<case name>/<what>".
#include "comparisons/suites/check.h"
#include "comparisons/suites/obstacles/cases.h"
#include "comparisons/suites/obstacles/settings.h"

#include <string>

namespace tecido::suites::obstacles {

/// Every check of the suite; `reference`: the Bullet checks as well (reference build).
CheckList declare_checks(const Settings& s, const Tolerances& tol, bool reference);

/// Records case `c`'s result: its values, or (a case that threw or went unstable) fails every
/// check of the case with the reason.
void record(CheckList& checks, const Settings& s, const Case& c, const io::Json& result);

/// The block artefact at matched placement (figs 10-13), from the two edges-off block runs in
/// `by_name` (case name -> result): how far the two scenes' edge insets differ, and, 484 particles
/// over 121, the deepest spring inside the block at the run's end per spacing and the share of the
/// springs across the top face's outline that pass through the block then. A missing, failed or
/// unstable run fails all three with the reason; a run with nothing through gives a non-finite
/// ratio, which fails.
void record_matched(CheckList& checks, const Settings& s, const io::Json& by_name);

}  // namespace tecido::suites::obstacles
