#pragma once
/// What the forced-contact experiment writes:
///  experiment.json: {"experiment":"forced-contact", "command", "tecido" (provenance), "quick",
///    "seeds", "settings":{holds, responses, after_release, dwell, censor, sample, bootstrap,
///    recovers_share, hold_margin}, "scene":{..every parameter..}, "scene_note",
///    "claims":[..as self-contact's..], "multiplicity",
///    "cells":[{"hold","response","runs","unstable","forced","held_pairs","recovered",
///              "recovered_ci95","median","median_ci95","restricted_mean","restricted_ci95",
///              "free_at_end","mean_series"}],
///    "errors":[..], "runs":[{"hold","response","seed", ..run.h's fields..} | {...,"error"}]}
///  (numbers that cannot be computed are null; a median that is not reached is "inf");
///  experiment.md: claims with verdicts, the rules, the scene note, the table per (response,
///  hold), the plots (intersecting pairs against time per response, one plot per hold:
///  forced_pairs_<h>.svg beside forced_pairs.dat), the method.
/// Nothing depends on the wall clock: the files are bit-identical at any thread count and after a
/// merge of shards (but for the provenance's command line).
#include "comparisons/suites/forced_contact/experiment.h"

#include <string>
#include <vector>

namespace tecido::suites::forced_contact {

std::string experiment_json(const Plan& plan, const Findings& f, const std::vector<io::Json>& results);
std::string experiment_markdown(const Plan& plan, const Findings& f);

}  // namespace tecido::suites::forced_contact
