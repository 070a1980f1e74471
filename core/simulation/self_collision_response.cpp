#include "core/simulation/self_collision_response.h"

#include "core/cloth/continuous_impulse.h"
#include "core/cloth/edge_response.h"
#include "core/geometry/tri_tri_intersect.h"

#include <algorithm>

namespace tecido {

namespace {
std::size_t contact_count(const ContinuousContacts& c) { return c.vertex_face.size() + c.edge_edge.size(); }
}  // namespace

SelfCollisionResponder::SelfCollisionResponder(const std::vector<std::array<int, 3>>& triangles, int vertex_count,
                                               const std::vector<Vec3>& x_build,
                                               const SelfCollisionSettings& settings)
    : settings_(settings), detector_(triangles, x_build), topo_(build_mesh_topology(vertex_count, triangles)) {
  detector_.set_threads(settings_.threads);
  if (settings_.detection != SelfCollisionDetection::Continuous) return;
  continuous_ = std::make_unique<ContinuousSelfCollisionDetector>(triangles, x_build);
  continuous_->set_threads(settings_.threads);
  vertex_tris_ = build_vertex_triangles(vertex_count, triangles);
  x_prev_ = x_build;
}

void SelfCollisionResponder::detect_continuous(Simulation& sim) {
  const Particles& p = sim.particles();
  pairs_.clear();
  const auto finite = [](const std::vector<Vec3>& x) {
    return std::all_of(x.begin(), x.end(), [](const Vec3& v) { return v.allFinite(); });
  };
  if (!finite(p.x) || !finite(x_prev_)) {  // the step is unstable; Simulation::step reports it
    contacts_ = ContinuousContacts{};
    return;
  }
  contacts_ = continuous_->detect(x_prev_, p.x);
  const SelfCollisionResponse r = settings_.response;
  if (r == SelfCollisionResponse::Impulse || r == SelfCollisionResponse::None || contact_count(contacts_) == 0) return;
  contact_triangle_pairs(contacts_, detector_.triangles(), vertex_tris_, pairs_);
  if (r != SelfCollisionResponse::Gia && r != SelfCollisionResponse::GiaEdge3) return;
  // GIA analyses intersections: keep the contacts' triangle pairs that intersect now.
  const auto& tris = detector_.triangles();
  pairs_.erase(std::remove_if(pairs_.begin(), pairs_.end(),
                              [&](const TrianglePair& q) {
                                const auto& a = tris[q[0]];
                                const auto& b = tris[q[1]];
                                return !tri_tri_intersect({p.x[a[0]], p.x[a[1]], p.x[a[2]]},
                                                          {p.x[b[0]], p.x[b[1]], p.x[b[2]]});
                              }),
               pairs_.end());
}

void SelfCollisionResponder::operator()(Simulation& sim) {
  const int every = settings_.every > 0 ? settings_.every : 1;
  if (sim.steps_done() % every != 0) return;
  Particles& p = sim.mutable_particles();
  const bool continuous = settings_.detection == SelfCollisionDetection::Continuous;
  if (continuous) {
    detect_continuous(sim);
  } else {
    pairs_ = detector_.detect(p.x);
  }
  ++stats_.checks;
  const std::size_t found = continuous ? contact_count(contacts_) : pairs_.size();
  stats_.last_pairs = found;
  if (found > 0) {
    ++stats_.contact_checks;
    stats_.pairs += static_cast<long long>(found);
    stats_.max_pairs = std::max<long long>(stats_.max_pairs, static_cast<long long>(found));
    if (settings_.response == SelfCollisionResponse::Impulse) {
      respond_impulse(sim);
    } else if (!continuous || !pairs_.empty()) {
      respond_pairs(sim);
    }
  }
  if (continuous) x_prev_ = p.x;
}

void SelfCollisionResponder::respond_impulse(Simulation& sim) {
  Particles& p = sim.mutable_particles();
  const double h = sim.scene().dt * (settings_.every > 0 ? settings_.every : 1);
  const ContinuousContacts* c = &contacts_;
  for (int round = 0; round < settings_.impulse_iterations; ++round) {
    const int applied = apply_contact_impulses(*c, detector_.triangles(), x_prev_, p.x, p.v, p.inv_mass, h);
    stats_.impulses += applied;
    if (applied == 0) break;  // nothing changed: what `c` holds remains
    c = &continuous_->detect(x_prev_, p.x);
    ++stats_.impulse_rounds;
    if (contact_count(*c) == 0) break;
  }
  stats_.impulse_unresolved += static_cast<long long>(contact_count(*c));
}

void SelfCollisionResponder::respond_pairs(Simulation& sim) {
  Particles& p = sim.mutable_particles();
  const double dt = sim.scene().dt;
  const double f = settings_.strength;
  const auto& tris = detector_.triangles();
  auto edge = [&](EdgeMode m, const std::uint8_t* skip) {
    stats_.pushed_particles += apply_edge_mode(m, topo_, tris, pairs_, skip, p.x, p.inv_mass, f, dt, p.v, mark_);
  };
  switch (settings_.response) {
    case SelfCollisionResponse::None:
    case SelfCollisionResponse::Impulse: return;
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
