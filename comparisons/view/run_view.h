#pragma once
/// The data of a run's page (`tecido run SCENE --out DIR` writes DIR/index.html, view_page.h):
/// the recorded frames of a scene's particles (the cloth), its obstacles' surfaces at each frame's
/// time, and per frame what core's detectors find:
///  - the pairs of cloth triangles in self-contact (core/cloth/self_collision.h, SelfCollisionDetector:
///    intersecting pairs that share no vertex), for a scene with triangles;
///  - the springs that pass through an obstacle (core/dynamics/springs_through_obstacle.h,
///    segment_through_obstacle), for a scene with springs and obstacles.
/// Data ({"kind":"run", ...}, base64.h for the arrays):
///   "title", "nodes": N, "frames": F, "steps": [step per frame], "times": [t per frame],
///   "positions": float32 F x N x 3, "triangles": uint32 3 per triangle, "springs": uint32 2 per spring,
///   "contacts": {"offsets": uint32 F + 1, "pairs": uint32 2 per pair}, "through": {"offsets":
///   uint32 F + 1, "springs": uint32 spring indices}, "obstacles": [{"vertices": V, "triangles":
///   uint32, "positions": float32 V x 3 (a still obstacle) or F x V x 3 (a moving one)}].
/// Frames with a non-finite position are skipped (as io::FrameWriter skips them).
#include "comparisons/io/json_reader.h"
#include "core/cloth/self_collision.h"
#include "core/scene/scene.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace tecido::view {

class RunView {
 public:
  explicit RunView(const Scene& scene);
  ~RunView();

  /// Records the frame of `step` at time t with positions x (one per particle of the scene).
  /// Returns false (nothing recorded) when a position is not finite.
  bool add(long long step, double t, const std::vector<Vec3>& x);

  long long frames() const { return static_cast<long long>(steps_.size()); }
  io::Json data(const std::string& title) const;

 private:
  const Scene& scene_;
  std::unique_ptr<SelfCollisionDetector> detector_;
  std::vector<long long> steps_;
  std::vector<double> times_;
  std::vector<float> positions_;
  std::vector<std::uint32_t> contact_offsets_{0}, contact_pairs_;
  std::vector<std::uint32_t> through_offsets_{0}, through_springs_;
  std::vector<std::vector<float>> obstacle_positions_;  ///< per obstacle, every frame
};

/// How many of a run's frames (recorded every `every` steps of `steps`, the first and the last) a
/// page keeps at most, the page's data being bounded (kMaxViewFloats float32 positions): 1 keeps
/// every frame, k every k-th.
long long view_frame_stride(long long steps, long long every, std::size_t particles);

/// About 200 MB of positions in a page at most.
constexpr double kMaxViewFloats = 5e7;

}  // namespace tecido::view
