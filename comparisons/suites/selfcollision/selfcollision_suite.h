#pragma once
/// Suite `selfcollision`: on frames recorded from running simulations (the seed's experiment
/// scene, a cloth crumpling onto a floor), the intersecting triangle-pair sets of every
/// self-collision engine (core's box tree + exact narrow phase, core brute force, FCL's BVH,
/// exact brute force) and of every outside engine answering tri_tri (--plugin, --engine-cmd) against
/// the exact truth: precision and recall per engine and source, and time per frame.
///
/// Layout: settings.h (what runs), frame_recorder.* (frames from a simulation), frame_sources.*
/// (one function per source, in a table), pair_agreement.* (precision and recall),
/// selfcollision_case.* (one source: record, truth, every engine), check_plan.* (the checks,
/// declared before anything runs), selfcollision_report.* (table and prose); this file builds the
/// sweep (one case per source) and assembles.
#include "comparisons/engines/outside/outside_engine.h"
#include "comparisons/engines/self_collision_engines.h"
#include "comparisons/suites/selfcollision/frame_sources.h"
#include "comparisons/suites/suite.h"
#include "comparisons/suites/sweep.h"

#include <vector>

namespace tecido::suites {

/// The suite as a sweep with `settings`, one case per source of `sources`, every engine of
/// `engines` and then of `outside` (outside engines answering tri_tri, run on core's broad-phase
/// candidates: selfcollision_case.h) against the truth: the engine named "exact" if present, else
/// "core-brute".
Sweep selfcollision_sweep_for(const SuiteContext& ctx, const selfcollision::Settings& settings,
                              std::vector<selfcollision::FrameSource> sources, std::vector<SelfCollisionEngine> engines,
                              std::vector<outside::OutsideEnginePtr> outside = {});
/// selfcollision_sweep_for with selfcollision::settings(ctx.quick), frame_sources(), the
/// registered engines --engines selects (the truth always) and the selected outside engines
/// answering tri_tri.
Sweep selfcollision_sweep(const SuiteContext& ctx);
SuiteResult run_selfcollision_suite(const SuiteContext& ctx);

}  // namespace tecido::suites
