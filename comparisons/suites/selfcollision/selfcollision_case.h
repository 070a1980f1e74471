#pragma once
/// One case of the `selfcollision` suite: a source's frames (frame_sources.h), the true pairs of
/// each frame by the truth engine, and every engine's pairs scored against them and timed.
#include "comparisons/engines/outside/outside_engine.h"
#include "comparisons/engines/self_collision_engines.h"
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/selfcollision/frame_disagreements.h"
#include "comparisons/suites/selfcollision/frame_sources.h"
#include "comparisons/suites/selfcollision/pair_agreement.h"

#include <string>
#include <vector>

namespace tecido::suites::selfcollision {

/// One engine on one source's frames.
struct EngineScore {
  std::string engine;
  long answered = 0;   ///< frames the engine answered (an unanswered frame is not scored)
  PairAgreement pairs;  ///< over the answered frames
  double seconds = 0.0;  ///< thread CPU time over all frames
};

/// A source's case: what was recorded and how each engine did; `error` when the case threw.
struct SourceScore {
  std::string error;
  long frames = 0, frames_with_contact = 0, true_pairs = 0, triangles = 0;
  std::vector<EngineScore> engines;
  KeptDisagreements disagreements;  ///< the frames where an engine's pairs differ from the truth's
};

/// Records `source`'s frames, asks `truth` (whose unanswered frame is an error) and each engine,
/// then each outside engine answering tri_tri (scored after the built-in ones).
SourceScore score_source(const FrameSource& source, const Settings& s, const std::string& data_dir,
                         const SelfCollisionEngine& truth, const std::vector<SelfCollisionEngine>& engines,
                         const std::vector<outside::OutsideEnginePtr>& outside = {});

/// An outside engine's intersecting pairs at positions x: its tri_tri answers, in one batch
/// through its door, on core's broad-phase candidates (the pairs whose boxes overlap and that
/// share no vertex: every pair that can touch); nullopt when it could not answer some pair.
/// Adds what the batch cost to `seconds` (this thread's CPU time, plus a process's round trips).
std::optional<std::vector<TrianglePair>> outside_pairs(outside::OutsideEngine& engine, const std::vector<Vec3>& x,
                                                       const std::vector<std::array<int, 3>>& triangles,
                                                       double& seconds);

/// A SourceScore as a case result (lossless), and back; a case error ({"error": ...}) reads back
/// as a SourceScore with only `error` set.
io::Json source_score_json(const SourceScore& s);
SourceScore source_score_from_json(const io::Json& j);

}  // namespace tecido::suites::selfcollision
