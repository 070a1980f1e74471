#pragma once
/// Continuous self-collision engines of one mesh moving linearly between two frames (the vertices
/// x0 move to x1, the triangles stay), by name: `tecido selfcollide --to` and the Python module's
/// continuous_self_collisions() both answer through here. Each returns every vertex-face pair
/// (vertex not a corner of the face) and edge-edge pair (no shared vertex) that touches during the
/// motion, sorted (core/cloth/continuous_self_collision.h). Engines:
///   core        core's broad phase over swept boxes and core's continuous test, each candidate then
///               confirmed by the exact referee: the exact answer, fast;
///   core-brute  core's test on every pair, unconfirmed: the brute-force reference of core's broad
///               phase (its pairs are core's candidates before confirmation, which may include near
///               misses within core's distance tolerance); at most io::kMaxBruteForceTriangles;
///   exact       the exact referee (reference/exact_ccd.h) on every pair; at most
///               kMaxExactContinuousTriangles.
#include "core/cloth/continuous_self_collision.h"

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace tecido {

/// Triangles the exact engine accepts: every vertex-face and edge-edge pair goes through the
/// exact referee (about 4.5 million edge pairs at this size).
constexpr std::size_t kMaxExactContinuousTriangles = std::size_t{1} << 11;

/// The engine names, in order.
const std::vector<std::string>& continuous_self_collision_engines();

/// io::UsageError "<option>: <engine> tests every pair and takes at most N triangles, but <mesh>
/// has M (use core)" when an all-pairs engine is given a mesh beyond its limit.
void check_continuous_self_collision_size(const std::string& engine, std::size_t triangles, const std::string& mesh,
                                          const std::string& option = "--engines");

/// Engine `name`'s contacts (std::invalid_argument for an unknown name). `threads` (>= 1) is how
/// many threads core's detection and the referee's confirmation of its candidates use; the answer
/// does not depend on it.
ContinuousContacts continuous_self_collision_contacts(const std::string& name, const std::vector<Vec3>& x0,
                                                      const std::vector<Vec3>& x1,
                                                      const std::vector<std::array<int, 3>>& triangles,
                                                      int threads = 1);

}  // namespace tecido
