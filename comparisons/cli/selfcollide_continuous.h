#pragma once
/// `tecido selfcollide --mesh START.obj --to END.obj [--engines core,core-brute,exact] --json`:
/// continuous self-collision of one mesh moving linearly between two frames (the vertices of
/// START move to those of END; both files must have the same vertex count and the same faces).
/// Prints {"<engine>":{"vertex_face":[[v,f],...],"edge_edge":[[[a,b],[c,d]],...]}}: every
/// vertex-face pair (vertex not a corner of the face) and edge-edge pair (no shared vertex) that
/// touches during the motion; 0-based OBJ vertex indices and face (triangle) order, a < b, c < d,
/// sorted. Engines: core, core-brute, exact (comparisons/engines/continuous_self_collision_engines.h).
/// Bad input (different vertex counts or faces, a mesh too large for an engine): exit 2.
#include <cstddef>
#include <string>
#include <vector>

namespace tecido::cli {

/// Runs the command on `threads` threads (>= 1: core's detection and the referee's confirmation
/// of its candidates; the output does not depend on it); returns the exit code. Throws
/// io::InputError / io::UsageError on bad input.
int run_selfcollide_continuous(const std::string& start, const std::string& end, const std::string& engines,
                               int threads = 1);

}  // namespace tecido::cli
