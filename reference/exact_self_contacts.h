#pragma once
/// The exact continuous self-collision of one mesh moving linearly between two frames: core's
/// broad phase and continuous test (no contact missed) give the candidates, and the exact referee
/// (exact_ccd.h, whether, not when) keeps those that touch. The answer of `tecido selfcollide --to`
/// (engine core), of the Python module's continuous_self_collisions() and of
/// tecido::referee::continuous_self_collisions.
#include "core/cloth/continuous_self_collision.h"

namespace tecido::reference {

/// `threads` (>= 1) runs core's detection and the confirmation on that many threads; the answer
/// does not depend on it.
ContinuousContacts exact_self_contacts(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                                       const std::vector<std::array<int, 3>>& triangles, int threads = 1);

}  // namespace tecido::reference
