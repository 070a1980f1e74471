#pragma once
/// Cloth self-collision in a running Simulation: a Simulation::post_step hook that, after
/// every `every`-th step (after the plane contacts), detects the intersecting triangle pairs
/// (self_collision.h) and applies the chosen response (self_collision_settings.h) as velocity
/// changes dv = F dt / m: GIA (gia.h) pulls each wrong-side region toward its partner, the
/// edge modes (edge_response.h) push the contact triangles' particles. Positions are never
/// moved by the response; the next step's integration carries the change.
/// It counts, per check, whether a self-contact was detected (the seed's "frames with
/// self-contact", tables 1-3) and how often GIA failed.
#include "core/cloth/gia.h"
#include "core/cloth/mesh_topology.h"
#include "core/cloth/self_collision.h"
#include "core/cloth/self_collision_settings.h"
#include "core/dynamics/simulation.h"

#include <memory>

namespace tecido {

struct SelfCollisionStats {
  long long checks = 0;                 ///< steps after which detection ran
  long long contact_checks = 0;         ///< ... and found at least one intersecting pair
  long long pairs = 0;                  ///< intersecting pairs, summed over checks
  long long max_pairs = 0;              ///< most pairs in one check
  long long gia_regions = 0;            ///< wrong-side regions found, summed (gia responses)
  long long gia_failed_checks = 0;      ///< checks where GIA left some pair unresolved
  long long gia_unresolved_pairs = 0;   ///< pairs GIA left unresolved, summed
  long long unseparated_cut_edges = 0;  ///< cut edges whose ends stay connected (border case), summed
  long long pushed_particles = 0;       ///< velocity changes applied, summed
  std::size_t last_pairs = 0;           ///< pairs found by the latest check
};

/// The hook's state: detector, topology, GIA workspace and counters.
class SelfCollisionResponder {
 public:
  /// For the mesh `triangles` over a vertex array of `vertex_count` particles, tree built on
  /// positions x_build.
  SelfCollisionResponder(const std::vector<std::array<int, 3>>& triangles, int vertex_count,
                         const std::vector<Vec3>& x_build, const SelfCollisionSettings& settings);

  /// Detects and responds on the simulation's current state (the post_step body).
  void operator()(Simulation& sim);

  const SelfCollisionStats& stats() const { return stats_; }
  const SelfCollisionSettings& settings() const { return settings_; }
  const MeshTopology& topology() const { return topo_; }
  const std::vector<TrianglePair>& last_pairs() const { return pairs_; }
  const GiaResult& last_gia() const { return gia_; }

 private:
  SelfCollisionSettings settings_;
  SelfCollisionDetector detector_;
  MeshTopology topo_;
  GiaResult gia_;
  std::vector<TrianglePair> pairs_;
  std::vector<std::uint8_t> mark_, skip_;
  SelfCollisionStats stats_;
};

/// When the simulation's scene has `self_collision` and a triangle mesh, installs a responder
/// as sim.post_step (replacing any hook) and returns it; otherwise returns nullptr.
std::shared_ptr<SelfCollisionResponder> install_self_collision(Simulation& sim);

}  // namespace tecido
