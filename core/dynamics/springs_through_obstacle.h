#pragma once
/// How many springs pass through an obstacle's interior at one state: the measure of the seed's
/// block artefact (figs. 10-13: the springs between particles resting on a block and particles
/// hanging beside it cut through the block's edge, fewer with more particles). A spring is a
/// straight segment between its two particles' positions; the obstacle is taken at its pose at
/// time t (obstacle_pose.h).
///  - box: the segment enters the open box (segment_box_depth > 0 in the box's frame,
///    segment_box.h): touching a face, edge or corner is not through;
///  - sphere: the segment's closest point to the centre is strictly inside the ball
///    (inside_sphere, segment_sphere.h);
///  - mesh: a mesh has no interior in the engine (it may be open); a spring counts when it
///    crosses a triangle's interior (its ends strictly on opposite sides of the triangle's plane and
///    the crossing strictly inside the triangle, exact orient3d signs).
#include "core/dynamics/spring.h"
#include "core/geometry/obstacle.h"

#include <vector>

namespace tecido {

/// Whether the segment a-b passes through obstacle `o`'s interior at time t (the rules above).
bool segment_through_obstacle(const Obstacle& o, double t, const Vec3& a, const Vec3& b);

/// The number of springs (i, j) whose segment x[i]-x[j] passes through obstacle `o`'s interior at
/// time t; pinned or free ends alike.
int springs_through_obstacle(const Obstacle& o, double t, const std::vector<Spring>& springs,
                             const std::vector<Vec3>& x);

}  // namespace tecido
