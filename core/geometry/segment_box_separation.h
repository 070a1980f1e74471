#pragma once
/// How to move a segment out of a box it cuts through, in the box's frame: the separating-axis
/// test (Gottschalk, Lin and Manocha 1996; Ericson 2005, section 5.2.1) over the box's three face
/// normals and the three cross products of the segment's direction with the box's axes (the
/// normals of the box's edges against the segment), taking the axis and side with the smallest
/// overlap: moving the segment that far along it separates them (the minimal translation along
/// those axes). A spring cutting a box's edge gets that edge's normal; one dipping under a face
/// its normal; one passing a corner the better of the two edges there.
#include "core/geometry/types.h"

namespace tecido {

struct SegmentBoxSeparation {
  bool cuts = false;            ///< the segment enters the open box (segment_box_depth > 0)
  Vec3 normal = Vec3::UnitZ();  ///< unit direction to move it, in the box's frame (out of the box)
  double overlap = 0.0;         ///< how far along `normal` (> 0 when cutting)
  /// Where along q0 -> q1 to push: the end that reaches deepest along the axis, or the deepest
  /// point when the segment is perpendicular to it (an edge's normal).
  double s = 0.5;
  /// For a segment that does not cut: its clearance, the largest gap along any of the axes (0
  /// when touching). The distance to the box is at least this.
  double clearance = 0.0;
};

SegmentBoxSeparation segment_box_separation(const Vec3& q0, const Vec3& q1, const Vec3& h);

/// The parameter s in [0, 1] of the segment's deepest point in the box (segment_box_depth's
/// argument of the maximum; 0.5 on a tie along the whole segment).
double segment_box_deepest(const Vec3& q0, const Vec3& q1, const Vec3& h);

}  // namespace tecido
