#pragma once
/// The `obstacles` suite's checks of Bullet's classic soft body on the suite's scenes (the runs
/// themselves are in bullet_cases.h, reference build only). Bullet-free, so the checks are
/// declared the same way in every build that runs the Bullet cases.
#include "comparisons/suites/check.h"
#include "comparisons/suites/obstacles/cases.h"
#include "comparisons/suites/obstacles/settings.h"

namespace tecido::suites::obstacles {

/// Per Bullet scene (bullet/sphere, bullet/block/<n>): onset_error_steps, |Bullet's contact onset
/// (the first step end at which a node leaves free fall) - the analytic fall to the surface| / dt.
/// Bullet's penetration, rest height and springs through the block are reported beside core's,
/// not checked: Bullet keeps a margin and pushes nodes out softly rather than holding a hard
/// constraint, so how deep its cloth sinks is a finding about Bullet, not an agreement to test.
void declare_bullet_checks(CheckList& checks, const Settings& s, const Tolerances& tol);

/// Records a Bullet case's result (bullet_cases.h) into its declared checks.
void record_bullet(CheckList& checks, const Case& c, const io::Json& result);

}  // namespace tecido::suites::obstacles
