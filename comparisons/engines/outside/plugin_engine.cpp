#include "comparisons/engines/outside/plugin_engine.h"

#include "comparisons/engines/outside/plugin_simulation.h"
#include "comparisons/engines/outside/scene_arrays.h"

#include <array>
#include <cstring>

namespace tecido::outside {

namespace {

template <std::size_t N>
std::array<double, 3 * N> flat(const std::array<Vec3, N>& pts) {
  std::array<double, 3 * N> out{};
  for (std::size_t i = 0; i < N; ++i)
    for (int c = 0; c < 3; ++c) out[3 * i + c] = pts[i][c];
  return out;
}

tecido_plane abi_plane(const BoundedPlane& p) {
  tecido_plane q{};
  for (int c = 0; c < 3; ++c) {
    q.position[c] = p.position[c];
    q.normal[c] = p.normal[c];
    q.forward[c] = p.forward[c];
  }
  q.half_extents[0] = p.half_extents.x();
  q.half_extents[1] = p.half_extents.y();
  return q;
}

}  // namespace

PluginEngine::PluginEngine(std::shared_ptr<PluginLibrary> library, const tecido_engine* engine)
    : library_(std::move(library)), engine_(engine), name_(engine->name),
      mutex_((engine->flags & TECIDO_ENGINE_THREAD_SAFE) ? nullptr : std::make_shared<std::mutex>()) {}

std::unique_lock<std::mutex> PluginEngine::guard() {
  return mutex_ ? std::unique_lock<std::mutex>(*mutex_) : std::unique_lock<std::mutex>();
}

Capabilities PluginEngine::capabilities() const {
  Capabilities c;
  c.tri_tri = engine_->tri_tri != nullptr;
  c.segment_plane = engine_->segment_plane != nullptr;
  c.ccd_vertex_face = engine_->ccd_vertex_face != nullptr;
  c.ccd_edge_edge = engine_->ccd_edge_edge != nullptr;
  c.dynamics = engine_->create != nullptr;
  return c;
}

std::optional<double> PluginEngine::claimed_order() const {
  if (engine_->claimed_order > 0.0) return engine_->claimed_order;
  return std::nullopt;
}

std::vector<std::optional<bool>> PluginEngine::tri_tri(const std::vector<TriTriQuery>& queries) {
  std::vector<std::optional<bool>> out(queries.size());
  auto lock = guard();
  for (std::size_t k = 0; k < queries.size(); ++k) {
    const auto a = flat(queries[k].a), b = flat(queries[k].b);
    const int r = engine_->tri_tri(a.data(), b.data());
    if (r == 0 || r == 1) out[k] = (r == 1);
  }
  return out;
}

std::vector<std::optional<SegmentPlaneHit>> PluginEngine::segment_plane(const std::vector<SegmentPlaneQuery>& queries) {
  std::vector<std::optional<SegmentPlaneHit>> out(queries.size());
  auto lock = guard();
  for (std::size_t k = 0; k < queries.size(); ++k) {
    const tecido_plane p = abi_plane(queries[k].plane);
    const std::array<double, 3> from{queries[k].from.x(), queries[k].from.y(), queries[k].from.z()};
    const std::array<double, 3> to{queries[k].to.x(), queries[k].to.y(), queries[k].to.z()};
    double t = 0.0;
    const int r = engine_->segment_plane(&p, from.data(), to.data(), &t);
    if (r == 0) out[k] = SegmentPlaneHit{false, 0.0};
    if (r == 1) out[k] = SegmentPlaneHit{true, t};
  }
  return out;
}

std::vector<std::optional<CcdAnswer>> PluginEngine::ccd(const std::vector<CcdQuery>& queries) {
  std::vector<std::optional<CcdAnswer>> out(queries.size());
  auto lock = guard();
  for (std::size_t k = 0; k < queries.size(); ++k) {
    const CcdQuery& q = queries[k];
    auto fn = q.kind == CcdKind::VertexFace ? engine_->ccd_vertex_face : engine_->ccd_edge_edge;
    if (!fn) continue;
    const auto t0 = flat(q.x0), t1 = flat(q.x1);
    double toi = 0.0;
    const int r = fn(t0.data(), t1.data(), &toi);
    if (r == 0) out[k] = CcdAnswer{false, 0.0};
    if (r == 1) out[k] = CcdAnswer{true, toi};
  }
  return out;
}

Creation PluginEngine::create(const Scene& scene) {
  const SceneArrays arrays = scene_arrays(scene);
  const tecido_scene view = arrays.view();
  char why[512];
  std::memset(why, 0, sizeof why);
  void* handle;
  {
    auto lock = guard();
    handle = engine_->create(&view, why, sizeof why);
  }
  Creation c;
  if (!handle) {
    why[sizeof why - 1] = '\0';
    c.refusal = why[0] ? why : "refused the scene without a reason";
    return c;
  }
  c.simulation = std::make_unique<PluginSimulation>(engine_, handle, scene.particles.size(), scene.dt, mutex_, library_);
  return c;
}

std::vector<std::shared_ptr<OutsideEngine>> plugin_engines(const std::shared_ptr<PluginLibrary>& library) {
  std::vector<std::shared_ptr<OutsideEngine>> out;
  for (std::size_t k = 0; k < library->table().engine_count; ++k)
    out.push_back(std::make_shared<PluginEngine>(library, &library->table().engines[k]));
  return out;
}

}  // namespace tecido::outside
