#pragma once
/// One run of the forced-contact experiment: the scene of scene.h stepped with its response and
/// the grips (the simulation's post_step moves the held particles, then the response acts, then
/// the exact discrete test (core/cloth/self_contact_counter.h, test "core") counts the
/// intersecting triangle pairs of the frame; counting never changes the run).
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/forced_contact/scene.h"
#include "comparisons/suites/forced_contact/settings.h"

#include <functional>
#include <string>
#include <vector>

namespace tecido::suites::forced_contact {

struct RunResult {
  std::string status = "ok";      ///< "ok" | "unstable"
  long long unstable_at_step = -1;
  std::vector<long long> series;  ///< intersecting pairs every Settings::sample seconds, from t = sample
  long long held_pairs = 0;       ///< pairs at the last held frame (before the grips let go)
  long long hold_max_pairs = 0;   ///< most pairs in a frame while the grips held (moving or still)
  bool recovered = false;         ///< free from some frame on, for at least the dwell before the horizon
  double recovery = 0.0;          ///< [s after release] start of the final free stretch (recovered runs)
  bool free_at_end = false;       ///< the last frame has no intersecting pair
};

/// Called after every step with the step number and the positions (frames for viewing).
using FrameFn = std::function<void(long long step, const Scene& scene, const std::vector<Vec3>& x)>;

/// Runs one (response, hold, run s).
RunResult run_forced(const ForcedScene& f, const Settings& s, SelfCollisionResponse response, double hold, int seed,
                     const FrameFn& on_frame = {});

/// The recovery of a run from the pairs of every frame after release (frame k at (k + 1) dt after
/// it): recovered when the final stretch of free frames begins at most censor_time after release;
/// its start (the time of its first frame).
void decide_recovery(const std::vector<long long>& after_release, double dt, const Settings& s, RunResult& r);

/// {"status","unstable_at_step","series","held_pairs","hold_max_pairs","recovered","recovery","free_at_end"}, and back.
io::Json run_json(const RunResult& r);
RunResult run_from_json(const io::Json& j);

}  // namespace tecido::suites::forced_contact
