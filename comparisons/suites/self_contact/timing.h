#pragma once
/// The seed's two claims about cost, measured on the experiment's own scene in the same run
/// (wall-clock, so outside the determinism promise; each is one case of the sweep, timed on one
/// thread while the other threads run other cases, with the compared parts interleaved so that
/// the load falls on both alike):
///  - section 3.1.3: the rotation test (fig. 18) was "extremely" slow, so Möller-Trumbore was
///    used, faster "even run twice": every pair of triangles sharing no vertex of frames recorded
///    from a no-response run, both tests over the same pairs, repeated, order alternating;
///  - sections 3.1.1 and 3.1.3: detecting collisions is the costliest part of a step. Per step
///    of a mode-3 run: the step itself (forces, integration), detection by brute force over all
///    pairs with the seed's Möller-Trumbore test (the O(n^2) the seed used), detection by the
///    harness's box tree with the exact test, and the edge response; summed over blocks of steps.
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/self_contact/claims.h"
#include "comparisons/suites/self_contact/settings.h"
#include "core/scene/scene.h"

#include <vector>

namespace tecido::suites::self_contact {

/// {"kind":"tritri-timing","pairs":P,"frames":F,"ns_per_pair_rotation":[..],"ns_per_pair_mt":[..],
///  "hits":{"core","core-mt","core-rotation"}} on `scene` (a no-response run).
io::Json time_tri_tri(const Scene& scene, const Settings& s);

/// {"kind":"phase-timing","steps_per_block":B,"pairs_found":{"detect_brute_mt","detect_bvh"},
///  "seconds_per_step":{"step":[..],"detect_brute_mt":[..],"detect_bvh":[..],"response":[..]}} (one value
/// per block) on `scene` (a mode-3 run).
io::Json time_phases(const Scene& scene, const Settings& s);

/// rotation-slower-than-mt, detection-dominates-step (brute force, the seed's) and
/// detection-dominates-step-bvh from those results; a null result (not run, or a case that
/// failed: `why`) gives inconclusive claims saying so.
/// mode1-marginal's cost half from the phase timing (claims.h: CostHalf); `why` when it is null.
CostHalf detection_cost(const io::Json* phases, const Settings& s, const std::string& why);

std::vector<Claim> timing_claims(const io::Json* tritri, const io::Json* phases, const Settings& s,
                                 const std::string& why);

}  // namespace tecido::suites::self_contact
