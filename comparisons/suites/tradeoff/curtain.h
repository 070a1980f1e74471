#pragma once
/// The `tradeoff` suite's scene, and the nudged copies its conditioning probes run.
#include "core/scene/scene.h"

#include <cstdint>

namespace tecido::suites::tradeoff {

/// A curtain: an n x n cloth, 1 m x 1 m, hanging in the vertical plane y = 0 (origin at the
/// top-left node, columns along +x, rows down along -z), released at rest from its rest shape,
/// pinned at its top corners (row 0, col 0) and (row 0, col n-1), total mass 0.1 kg, type B springs
/// 1 N/m, type A springs 0.5 N/m, no damping, gravity (0, 0, -9.81) m/s^2, no planes. Gravity lies
/// in the cloth's plane, so the motion does too: that keeps the problem well-conditioned (out of
/// the plane the sagging top edge buckles and a 1e-12 m nudge grows by orders of magnitude within
/// the second; the suite measures both).
Scene hanging_cloth(int n);

/// `scene` with every free node moved by `size` [m] in a seeded random direction, within the
/// cloth's plane (y = 0) or out of it (along +-y).
Scene nudged(const Scene& scene, std::uint64_t seed, bool out_of_plane, double size);

}  // namespace tecido::suites::tradeoff
