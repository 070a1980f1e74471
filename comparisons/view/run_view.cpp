#include "comparisons/view/run_view.h"

#include "comparisons/io/obstacle_surfaces.h"
#include "comparisons/view/base64.h"
#include "core/dynamics/springs_through_obstacle.h"

#include <cmath>

namespace tecido::view {

namespace {

void append_positions(std::vector<float>& out, const std::vector<Vec3>& x) {
  for (const Vec3& p : x)
    for (int c = 0; c < 3; ++c) out.push_back(static_cast<float>(p[c]));
}

bool finite(const std::vector<Vec3>& x) {
  for (const Vec3& p : x)
    if (!p.allFinite()) return false;
  return true;
}

std::vector<std::uint32_t> flat_triangles(const std::vector<std::array<int, 3>>& tris) {
  std::vector<std::uint32_t> out;
  for (const auto& t : tris)
    for (int v : t) out.push_back(static_cast<std::uint32_t>(v));
  return out;
}

/// The obstacle's positions: one frame when every frame equals the first (a still obstacle).
std::vector<float> still_or_all(const std::vector<float>& all, std::size_t per_frame) {
  for (std::size_t k = per_frame; k < all.size(); ++k)
    if (all[k] != all[k % per_frame]) return all;
  return std::vector<float>(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(std::min(per_frame, all.size())));
}

}  // namespace

RunView::RunView(const Scene& scene) : scene_(scene), obstacle_positions_(scene.obstacles.size()) {
  if (!scene.triangles.empty())
    detector_ = std::make_unique<SelfCollisionDetector>(scene.triangles, scene.particles.x);
}

RunView::~RunView() = default;

bool RunView::add(long long step, double t, const std::vector<Vec3>& x) {
  if (!finite(x)) return false;
  steps_.push_back(step);
  times_.push_back(t);
  append_positions(positions_, x);
  if (detector_)
    for (const TrianglePair& p : detector_->detect(x))
      for (int k : p) contact_pairs_.push_back(static_cast<std::uint32_t>(k));
  contact_offsets_.push_back(static_cast<std::uint32_t>(contact_pairs_.size() / 2));
  const auto& springs = scene_.forces.springs;
  for (std::size_t s = 0; s < springs.size(); ++s)
    for (const Obstacle& o : scene_.obstacles)
      if (segment_through_obstacle(o, t, x[springs[s].i], x[springs[s].j])) {
        through_springs_.push_back(static_cast<std::uint32_t>(s));
        break;
      }
  through_offsets_.push_back(static_cast<std::uint32_t>(through_springs_.size()));
  const std::vector<io::SurfaceMesh> surfaces = io::obstacle_surfaces(scene_.obstacles, t);
  for (std::size_t k = 0; k < surfaces.size(); ++k) append_positions(obstacle_positions_[k], surfaces[k].vertices);
  return true;
}

io::Json RunView::data(const std::string& title) const {
  std::vector<std::uint32_t> springs;
  for (const Spring& s : scene_.forces.springs) springs.push_back(s.i), springs.push_back(s.j);
  io::Json obstacles = io::Json::array();
  const std::vector<io::SurfaceMesh> surfaces = io::obstacle_surfaces(scene_.obstacles, 0.0);
  for (std::size_t k = 0; k < surfaces.size(); ++k) {
    const std::size_t per_frame = surfaces[k].vertices.size() * 3;
    obstacles.push_back({{"vertices", surfaces[k].vertices.size()},
                         {"triangles", uint32_base64(flat_triangles(surfaces[k].triangles))},
                         {"positions", float32_base64(still_or_all(obstacle_positions_[k], per_frame))}});
  }
  return {{"kind", "run"},
          {"title", title},
          {"nodes", scene_.particles.x.size()},
          {"frames", steps_.size()},
          {"steps", steps_},
          {"times", times_},
          {"positions", float32_base64(positions_)},
          {"triangles", uint32_base64(flat_triangles(scene_.triangles))},
          {"springs", uint32_base64(springs)},
          {"contacts", {{"offsets", uint32_base64(contact_offsets_)}, {"pairs", uint32_base64(contact_pairs_)}}},
          {"through", {{"offsets", uint32_base64(through_offsets_)}, {"springs", uint32_base64(through_springs_)}}},
          {"obstacles", obstacles}};
}

long long view_frame_stride(long long steps, long long every, std::size_t particles) {
  const double frames = static_cast<double>(steps / every + 2);
  const double floats = frames * static_cast<double>(particles) * 3.0;
  return floats <= kMaxViewFloats ? 1 : static_cast<long long>(std::ceil(floats / kMaxViewFloats));
}

}  // namespace tecido::view
