#pragma once
/// The suite's own measurement of the seed's block artefact (figs 10-13: springs cutting through
/// the block's edge): how deep a straight segment (a spring) goes into an oriented box, and how
/// many of a cloth's springs pass through its interior. Written here, independently of the
/// engine's contact code, so the engine is measured by something it does not share.
#include "core/geometry/types.h"

#include <array>
#include <vector>

namespace tecido::suites::obstacles {

/// An oriented box: centre, local axes as the columns of `rotation`, half extents along them.
struct OrientedBox {
  Vec3 center = Vec3::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Vec3 half = Vec3::Zero();
};

/// The largest depth over the segment p0 -> p1 of min_i (half_i - |q_i|) (q: the point in the
/// box's frame), i.e. how far its deepest point lies inside every face; <= 0 when the segment does
/// not enter the open box. The depth is the minimum of six functions linear along the segment,
/// so its maximum over [0, 1] is at an end or where two of them are equal: those candidates are
/// evaluated (a one-dimensional linear programme solved by enumeration).
double segment_box_interior_depth(const Vec3& p0, const Vec3& p1, const OrientedBox& box);

/// The number of springs (i, j) of positions x whose segment goes deeper than `min_depth` [m]
/// into the box, and (when `deepest` is set) the deepest such depth (0 when none).
int springs_through_box(const std::vector<Vec3>& x, const std::vector<std::array<int, 2>>& springs,
                        const OrientedBox& box, double min_depth, double* deepest = nullptr);

/// How far x lies inside the box (min_i (half_i - |q_i|)); <= 0 outside or on the surface.
double point_box_depth(const Vec3& x, const OrientedBox& box);

}  // namespace tecido::suites::obstacles
