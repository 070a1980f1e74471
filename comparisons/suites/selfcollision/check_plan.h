#pragma once
/// The `selfcollision` suite's checks: precision and recall of every engine but the truth on
/// every frame source, declared from the source table, the engines and the tolerance file before
/// any frame is recorded; then set, or failed with a reason, from each source's score.
#include "comparisons/suites/check.h"
#include "comparisons/suites/selfcollision/frame_sources.h"
#include "comparisons/suites/selfcollision/selfcollision_case.h"

#include <string>
#include <vector>

namespace tecido::suites::selfcollision {

/// "selfcollision/<engine>/<source>/<measure>", measure "precision" or "recall".
std::string check_name(const std::string& engine, const std::string& source, const std::string& measure);

/// For each engine but `truth`, each source: precision and recall, each at least
/// /selfcollision/<engine>_min (an outside engine, named in `outside`: /selfcollision/outside_min;
/// io::InputError when the file lacks it) and at most 1.
CheckList declare_checks(const std::vector<FrameSource>& sources, const std::vector<std::string>& engines,
                         const std::string& truth, const Tolerances& tol, const std::vector<std::string>& outside = {});

/// Records the checks of `source` from its score. Failed with a reason instead of a value: every
/// check of the source when its case threw; an engine's two checks when it left frames
/// unanswered; recall when the frames hold no true pair (a recall of nothing proves nothing).
/// `engines` are the names the checks were declared for (a failed case has no scores to name them).
void record_checks(CheckList& checks, const std::string& source, const std::vector<std::string>& engines,
                   const SourceScore& score);

}  // namespace tecido::suites::selfcollision
