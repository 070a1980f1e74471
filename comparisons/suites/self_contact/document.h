#pragma once
/// experiment.json of the self-contact experiment:
///  {"experiment":"self-contact", "command" (the options that redo it), "tecido" (version, commit and the
///   command line that wrote it, io/provenance.h), "scene", "seed_table", "simulated_time", "quick", "seeds",
///   "detectors":[..], "elasticity_as", "strength", "interpretation":{..} (the baseline reading),
///   "wind_model":{..},
///   "calibration":{"file","fitted","fit_cells","record":{..},"agreement":{"fit":{..},"prediction":{..}}},
///   "claims":[{"id","detector","statement","seed","seed_text","observed","observed_text","ci95":[lo,hi],
///              "n","unit","verdict","rule","reason","wall_clock","robustness"}],
///   "cells":[72 x {"index","elasticity","dt","wind","mode","role","seed_value","detector","mean","sd",
///              "ci95":[lo,hi],"pi95":[lo,hi],"n","seed_percentile","seed_in_pi95","by_detector":{..}}],
///   "sensitivity":{"variants":[..],"rows":[..],"robustness":[..]},
///   "timing":{"tritri":{..},"phases":{..}}, "errors":[..],
///   "runs":[{"index","seed","elasticity","dt","wind","mode","frames","contact_frames","share","status",
///            "unstable_at_step","pairs","max_pairs","by_detector":{..}} | {...,"error"}]}
/// Numbers that cannot be computed are null. "runs" lists the baseline's runs; top-level counts in
/// a run, like "mean" in a cell, are the first detector's. Wall-clock values are only in "timing"
/// and in the claims marked "wall_clock": true; everything else is bit-identical at any thread
/// count and after a merge of shards.
#include "comparisons/suites/self_contact/findings.h"

#include <string>
#include <vector>

namespace tecido::suites::self_contact {

std::string experiment_json(const Plan& plan, const Findings& f, const std::vector<io::Json>& results);

/// A claim as JSON (ordered keys, as in the file).
nlohmann::ordered_json claim_json(const Claim& c);

}  // namespace tecido::suites::self_contact
