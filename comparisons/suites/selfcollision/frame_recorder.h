#pragma once
/// Frames recorded from a running simulation, for the `selfcollision` suite: positions of a
/// triangle mesh at chosen steps, mostly ones where the mesh touches itself.
#include "core/scene/scene.h"

#include <array>
#include <vector>

namespace tecido::suites::selfcollision {

struct Frame {
  double time = 0.0;  ///< simulated time of the frame [s]
  std::vector<Vec3> x;
};

/// A source's frames and the mesh they are frames of.
struct FrameSet {
  std::vector<std::array<int, 3>> triangles;
  std::vector<Frame> frames;
};

/// Steps `scene` (core's Simulation) up to `steps` times and, every `every` steps, keeps the frame
/// while fewer than round(count x contact_share) frames with a self-intersection (by core's
/// detector) and fewer than the rest without one are kept; stops at `count` frames, at `steps`,
/// or when the run goes unstable.
FrameSet record_frames(const Scene& scene, long long steps, long long every, int count, double contact_share);

}  // namespace tecido::suites::selfcollision
