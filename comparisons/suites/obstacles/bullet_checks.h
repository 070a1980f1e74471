#pragma once
/// The `obstacles` suite's checks of Bullet's classic soft body on the suite's scenes (the runs
/// themselves are in bullet_cases.h, reference build only). Bullet-free, so the checks are
/// declared the same way in every build that runs the Bullet cases.
#include "comparisons/suites/check.h"
#include "comparisons/suites/obstacles/cases.h"
#include "comparisons/suites/obstacles/settings.h"

namespace tecido::suites::obstacles {

/// Per Bullet scene (bullet/sphere, bullet/block/<n>): onset_error (first step end with a node
/// within Bullet's contact distance of the surface, against the analytic fall to that distance),
/// max_penetration (deepest node inside the obstacle over the run, measured here: Bullet keeps a
/// margin, not a hard constraint), rest_height_difference (|Bullet's rest height - core's|).
void declare_bullet_checks(CheckList& checks, const Settings& s, const Tolerances& tol);

/// Records a Bullet case's result (bullet_cases.h) into its declared checks.
void record_bullet(CheckList& checks, const Case& c, const io::Json& result);

}  // namespace tecido::suites::obstacles
