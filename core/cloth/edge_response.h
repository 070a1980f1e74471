#pragma once
/// The seed's own self-contact response for contacts near a border (section 3.1.3, fig. 20):
/// every particle of a triangle involved in a detected contact is pushed, relative to its
/// mesh neighbours p- (the neighbour nearest the border) and p+ (the farthest from it):
///   mode 1: away from p-            d = p - p-
///   mode 2: toward p+               d = p+ - p
///   mode 3: toward (p+ + p-)/2      d = (p+ + p-)/2 - p
///
/// Definitions (the seed gives none):
///  - neighbours of p: the vertices joined to p by a mesh edge (on the builder's grid: left,
///    right, up, down and the a-d diagonal; mesh_topology.h);
///  - "distance to the border": MeshTopology::border_distance, edge hops to the nearest
///    boundary vertex; on the builder's grid min(r, c, rows-1-r, cols-1-c);
///  - p- = mean position of the neighbours whose border distance is the smallest among the
///    neighbours; p+ = mean position of those whose distance is the largest (ties are averaged,
///    so the result does not depend on vertex numbering). For a particle on the border, p- is
///    the mean of its border neighbours; on a straight border at rest that is p itself, and
///    mode 1 has no direction there.
///  - the push is a force of constant magnitude `strength` [N] along the unit direction d,
///    applied for one step as a velocity change dv = strength * dt * inv_mass * d/|d|; nothing
///    when |d| <= 1e-9 times the mean distance from p to its neighbours, nothing for pinned
///    particles. A particle in several contact triangles is pushed once per step.
/// Mode 3's target is the midpoint of two opposite neighbours: at rest it is p itself, so the
/// mode acts as a local smoothing force that only pushes where the cloth is bent or folded.
#include "core/cloth/mesh_topology.h"
#include "core/cloth/self_collision.h"

#include <cstdint>
#include <vector>

namespace tecido {

enum class EdgeMode { AwayFromNearer = 1, TowardFarther = 2, TowardMidpoint = 3 };

/// p- and p+ of vertex i (see the file comment); both equal x[i] when i has no neighbour.
struct BorderNeighbours {
  Vec3 nearer = Vec3::Zero();   ///< p-
  Vec3 farther = Vec3::Zero();  ///< p+
};
BorderNeighbours border_neighbours(const MeshTopology& topo, const std::vector<Vec3>& x, int i);

/// Unit push direction of `mode` for vertex i at positions x; zero when undefined (see above).
Vec3 edge_mode_direction(EdgeMode mode, const MeshTopology& topo, const std::vector<Vec3>& x, int i);

/// Pushes every free particle of the triangles in `pairs` (skipping pair k when
/// skip_pair && skip_pair[k]) by dv = strength * dt * inv_mass * direction, each particle once.
/// Directions use positions x only, so the order of particles does not matter. `mark` is a
/// reusable scratch buffer. Returns the number of particles pushed.
int apply_edge_mode(EdgeMode mode, const MeshTopology& topo, const std::vector<std::array<int, 3>>& triangles,
                    const std::vector<TrianglePair>& pairs, const std::uint8_t* skip_pair, const std::vector<Vec3>& x,
                    const std::vector<double>& inv_mass, double strength, double dt, std::vector<Vec3>& v,
                    std::vector<std::uint8_t>& mark);

}  // namespace tecido
