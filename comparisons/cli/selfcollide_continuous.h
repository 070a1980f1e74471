#pragma once
/// `tecido selfcollide --mesh START.obj --to END.obj [--engines core,core-brute,exact] --json`:
/// continuous self-collision of one mesh moving linearly between two frames (the vertices of
/// START move to those of END; both files must have the same vertex count and the same faces).
/// Prints {"<engine>":{"vertex_face":[[v,f],...],"edge_edge":[[[a,b],[c,d]],...]}}: every
/// vertex-face pair (vertex not a corner of the face) and edge-edge pair (no shared vertex) that
/// touches during the motion; 0-based OBJ vertex indices and face (triangle) order, a < b, c < d,
/// sorted. Engines:
///   core        core's broad phase over swept boxes and core's continuous test
///               (core/cloth/continuous_self_collision.h), each candidate then confirmed by the
///               exact referee: the exact answer, fast;
///   core-brute  core's test on every pair, unconfirmed: the brute-force reference of core's broad
///               phase (its pairs are core's candidates before confirmation, which may include
///               near misses within core's distance tolerance); at most kMaxBruteForceTriangles;
///   exact       the exact referee (reference/exact_ccd.h) on every pair; at most
///               kMaxExactContinuousTriangles.
/// Bad input (different vertex counts or faces, a mesh too large for an engine): exit 2.
#include <cstddef>
#include <string>
#include <vector>

namespace tecido::cli {

/// Triangles core-brute accepts: the same name and value as the shared table of input limits
/// other commands use (kept here until that table is shared).
constexpr std::size_t kMaxBruteForceTriangles = std::size_t{1} << 14;
/// Triangles the exact engine accepts: every vertex-face and edge-edge pair goes through the
/// exact referee (about 4.5 million edge pairs at this size).
constexpr std::size_t kMaxExactContinuousTriangles = std::size_t{1} << 11;

/// Runs the command on `threads` threads (>= 1: core's detection and the referee's confirmation
/// of its candidates; the output does not depend on it); returns the exit code. Throws
/// io::InputError / io::UsageError on bad input.
int run_selfcollide_continuous(const std::string& start, const std::string& end, const std::string& engines,
                               int threads = 1);

/// The engine names it knows, in order (exact only in the reference build).
const std::vector<std::string>& continuous_selfcollide_engines();

}  // namespace tecido::cli
