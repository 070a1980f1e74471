#pragma once
/// Cloth self-collision in a running Simulation: a Simulation::post_step hook that, after
/// every `every`-th step (after the plane contacts), detects self-contacts and applies the
/// chosen response (self_collision_settings.h).
///  - Discrete detection (the default): the intersecting triangle pairs of the current frame
///    (self_collision.h).
///  - Continuous detection: the vertex-face and edge-edge pairs that touch while the mesh moves
///    linearly from the positions of the previous check (the start, at the first check) to the
///    current ones (continuous_self_collision.h, core's test: no contact missed); for the
///    pair-based responses, their triangle pairs (contact_triangles.h).
/// Responses as velocity changes dv = F dt / m: GIA (gia.h) pulls each wrong-side region toward
/// its partner, the edge modes (edge_response.h) push the contact triangles' particles; positions
/// are not moved, the next step's integration carries the change. The impulse response
/// (continuous only, continuous_impulse.h) changes velocities and moves the current positions
/// with them (x += h dv, h the interval since the previous check), detecting again up to
/// `impulse_iterations` rounds, so that the interval ends without the contacts it found.
/// It counts, per check, whether a self-contact was detected (the seed's "frames with
/// self-contact", tables 1-3) and how often GIA failed.
#include "core/cloth/contact_triangles.h"
#include "core/cloth/continuous_self_collision.h"
#include "core/cloth/gia.h"
#include "core/cloth/mesh_topology.h"
#include "core/cloth/self_collision.h"
#include "core/cloth/self_collision_settings.h"
#include "core/simulation/simulation.h"

#include <memory>

namespace tecido {

struct SelfCollisionStats {
  long long checks = 0;                 ///< steps after which detection ran
  long long contact_checks = 0;         ///< ... and found at least one intersecting pair (contact, when continuous)
  long long pairs = 0;                  ///< intersecting pairs (continuous: vertex-face + edge-edge contacts), summed
  long long max_pairs = 0;              ///< most pairs in one check
  long long gia_regions = 0;            ///< wrong-side regions found, summed (gia responses)
  long long gia_failed_checks = 0;      ///< checks where GIA left some pair unresolved
  long long gia_unresolved_pairs = 0;   ///< pairs GIA left unresolved, summed
  long long unseparated_cut_edges = 0;  ///< cut edges whose ends stay connected (border case), summed
  long long pushed_particles = 0;       ///< velocity changes applied, summed
  long long impulses = 0;               ///< impulse response: contact impulses applied, summed
  long long impulse_rounds = 0;         ///< ... detection rounds after the first, summed
  long long impulse_unresolved = 0;     ///< ... contacts still found after the last round, summed
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
  /// Continuous detection: the contacts of the latest check (its first round).
  const ContinuousContacts& last_contacts() const { return contacts_; }

  const SelfCollisionStats& stats() const { return stats_; }
  const SelfCollisionSettings& settings() const { return settings_; }
  const MeshTopology& topology() const { return topo_; }
  /// The triangle pairs of the latest check: intersecting (discrete); the contacts' triangles
  /// (continuous, with the pair-based responses; GIA's: those intersecting now); none otherwise.
  const std::vector<TrianglePair>& last_pairs() const { return pairs_; }
  const GiaResult& last_gia() const { return gia_; }

 private:
  /// Continuous detection: contacts since the previous check, and their triangle pairs.
  void detect_continuous(Simulation& sim);
  /// The impulse response's rounds on the current state (continuous_impulse.h).
  void respond_impulse(Simulation& sim);
  /// The pair-based responses on pairs_ (GIA, edge modes).
  void respond_pairs(Simulation& sim);

  SelfCollisionSettings settings_;
  SelfCollisionDetector detector_;
  std::unique_ptr<ContinuousSelfCollisionDetector> continuous_;  ///< continuous detection only
  VertexTriangles vertex_tris_;                                  ///< continuous detection only
  std::vector<Vec3> x_prev_;                                     ///< positions at the previous check
  ContinuousContacts contacts_;
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
