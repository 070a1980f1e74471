#pragma once
/// One run of the experiment (one case of its sweep): a scene from scene_applier.h simulated for
/// its steps, every frame (step) checked for self-contact by each counting detector
/// (core/cloth/self_contact_counter.h), while the response acts on what the scene's own detector
/// (the exact `core`) finds. Counting never changes the run, so the detectors are compared on
/// the same frames.
/// With `premise`, each frame with an exact contact is also analysed the way GIA would
/// (core/cloth/gia.h): does an intersecting triangle reach the cloth's border, does GIA leave a
/// pair it cannot resolve (its flood cannot separate the sides), does a cut edge stay connected.
#include "comparisons/io/json_reader.h"
#include "core/cloth/self_contact_counter.h"
#include "core/scene/scene.h"

#include <string>
#include <vector>

namespace tecido::suites::self_contact {

/// Frames with an exact contact, and among them those the seed's premise is about.
struct PremiseCount {
  long long contact_frames = 0;      ///< frames with an intersecting pair (exact)
  long long border_frames = 0;       ///< ... where an intersecting triangle has a border vertex
  long long unresolved_frames = 0;   ///< ... where GIA leaves some pair unresolved
  long long unseparated_frames = 0;  ///< ... where some cut edge's ends stay connected (open curve)
};

struct RunResult {
  std::vector<SelfContactCount> counts;  ///< one per counting detector, in the order asked
  std::string status = "ok";             ///< "ok" | "unstable"
  long long unstable_at_step = -1;
  PremiseCount premise;                  ///< zero unless asked for
};

/// Runs `scene` (which has self_collision and a cloth) and counts with `detectors`.
RunResult run_scene(const Scene& scene, const std::vector<ContactTest>& detectors, bool premise);

/// A result as JSON {"status","unstable_at_step","counts":[[frames,contact_frames,pairs,max_pairs],...],
/// "premise":[contact,border,unresolved,unseparated]} (premise only when asked), and back.
io::Json run_json(const RunResult& r, bool premise);
RunResult run_from_json(const io::Json& j);

/// contact_frames / frames of detector d, NaN when no frame was counted.
double share(const RunResult& r, std::size_t d);

}  // namespace tecido::suites::self_contact
