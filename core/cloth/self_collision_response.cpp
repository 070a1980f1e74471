#include "core/cloth/self_collision_response.h"

#include "core/cloth/edge_response.h"

namespace tecido {

SelfCollisionResponder::SelfCollisionResponder(const std::vector<std::array<int, 3>>& triangles, int vertex_count,
                                               const std::vector<Vec3>& x_build,
                                               const SelfCollisionSettings& settings)
    : settings_(settings), detector_(triangles, x_build), topo_(build_mesh_topology(vertex_count, triangles)) {}

void SelfCollisionResponder::operator()(Simulation& sim) {
  const int every = settings_.every > 0 ? settings_.every : 1;
  if (sim.steps_done() % every != 0) return;
  Particles& p = sim.mutable_particles();
  pairs_ = detector_.detect(p.x);
  ++stats_.checks;
  stats_.last_pairs = pairs_.size();
  if (pairs_.empty()) return;
  ++stats_.contact_checks;
  stats_.pairs += static_cast<long long>(pairs_.size());
  stats_.max_pairs = std::max<long long>(stats_.max_pairs, static_cast<long long>(pairs_.size()));

  const double dt = sim.scene().dt;
  const double f = settings_.strength;
  const auto& tris = detector_.triangles();
  auto edge = [&](EdgeMode m, const std::uint8_t* skip) {
    stats_.pushed_particles += apply_edge_mode(m, topo_, tris, pairs_, skip, p.x, p.inv_mass, f, dt, p.v, mark_);
  };
  switch (settings_.response) {
    case SelfCollisionResponse::None: return;
    case SelfCollisionResponse::Edge1: edge(EdgeMode::AwayFromNearer, nullptr); return;
    case SelfCollisionResponse::Edge2: edge(EdgeMode::TowardFarther, nullptr); return;
    case SelfCollisionResponse::Edge3: edge(EdgeMode::TowardMidpoint, nullptr); return;
    case SelfCollisionResponse::Gia:
    case SelfCollisionResponse::GiaEdge3: break;
  }
  analyse_intersections(p.x, tris, topo_, pairs_, gia_);
  stats_.gia_regions += static_cast<long long>(gia_.regions.size());
  stats_.unseparated_cut_edges += gia_.unseparated_cut_edges;
  if (gia_.unresolved_pairs > 0) {
    ++stats_.gia_failed_checks;
    stats_.gia_unresolved_pairs += gia_.unresolved_pairs;
  }
  // Pull every vertex of every wrong-side region (positions unchanged, so order is irrelevant).
  for (std::size_t i = 0; i < p.x.size(); ++i) {
    const int c = gia_.component[i];
    if (c < 0 || !gia_.wrong_side[c] || p.inv_mass[i] == 0.0) continue;
    const Vec3& d = gia_.pull[c];
    if (d == Vec3::Zero()) continue;
    p.v[i] += (f * dt * p.inv_mass[i]) * d;
    ++stats_.pushed_particles;
  }
  if (settings_.response == SelfCollisionResponse::GiaEdge3 && gia_.unresolved_pairs > 0) {
    // Edge mode 3 on the pairs GIA leaves alone: skip the resolved ones.
    skip_.assign(gia_.pair_resolved.begin(), gia_.pair_resolved.end());
    edge(EdgeMode::TowardMidpoint, skip_.data());
  }
}

std::shared_ptr<SelfCollisionResponder> install_self_collision(Simulation& sim) {
  const Scene& s = sim.scene();
  if (!s.self_collision || s.triangles.empty()) return nullptr;
  auto r = std::make_shared<SelfCollisionResponder>(s.triangles, static_cast<int>(sim.particles().size()),
                                                    sim.particles().x, *s.self_collision);
  sim.post_step = [r](Simulation& simulation) { (*r)(simulation); };
  return r;
}

}  // namespace tecido
