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

/// The seed's direction (figs 10-13: less cutting with more particles), from the two edges-off
/// block runs in `by_name` (case name -> result): share and depth ratios, finer over coarser; a
/// missing or failed run fails both with the reason.
void record_direction(CheckList& checks, const Settings& s, const io::Json& by_name);

}  // namespace tecido::suites::obstacles
