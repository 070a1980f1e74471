#pragma once
/// Particles against obstacles (spheres, boxes, triangle meshes; static or moving), the part of
/// the simulation's contact event loop that is not planes (simulation.h). Over each interval
/// [t0, t1] of the loop a particle moves along the straight segment x0 -> x1 and every obstacle
/// from its pose at t0 to its pose at t1; the tests are continuous over that motion:
///  - sphere: the segment relative to the centre against the open ball (segment_sphere.h);
///  - box: the segment in the box's frame against the open box (segment_box.h);
///  - mesh: core's continuous vertex-face test (ccd/ccd.h) of the particle against each moving
///    triangle, with the side of each triangle's plane remembered per (particle, triangle), as
///    for two-sided planes: a triangle is only tested when the particle does not end strictly on
///    its remembered side, and a side changes without a contact only when the particle went round
///    the triangle (mesh_obstacle_contacts.h).
/// Spheres and boxes are solid: a step never ends with a free particle strictly inside one (the
/// inside tests inside_sphere / inside_box; an end point inside is always a hit). A mesh, closed
/// or open, is a set of two-sided triangles: no particle crosses one.
///
/// Response (seed eq. 9) relative to the surface's velocity (obstacle_response.h) at the point
/// where the particle's path reaches the surface, the particle placed there on the obstacle's
/// pose at the end of the bracket (so nothing is left inside at any step size). A static contact
/// becomes a resting contact, as on planes: the obstacle cancels the normal part of the
/// particle's acceleration while it pushes in, friction acts once per step, and the contact is
/// released when the free acceleration pulls away (on a sphere, when it cannot hold the particle
/// on the curve: a.n + |v_t|^2 / r > 0), the particle leaves the face or triangle, or something
/// else (a spring held over an edge, edge_contacts.h) lifted it off the surface by more than
/// kLiftTolerance times the coordinates' size.
#include "core/dynamics/obstacle_poses.h"
#include "core/dynamics/particles.h"
#include "core/dynamics/plane_contact.h"
#include "core/geometry/obstacle.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace tecido {

/// A particle's earliest contact with an obstacle over the interval.
struct ObstacleHit {
  int particle = -1;
  int obstacle = -1;
  int feature = 0;  ///< box face (segment_box.h numbering), mesh triangle; 0 for a sphere
  double s = 2.0;   ///< fraction of the interval (along x0 -> x1) at which it reaches the surface
};

/// A resting contact: the particle lies on the feature; `normal` points out of the obstacle at
/// the particle, as at the start of the current step.
struct ObstacleRest {
  int particle = -1;
  int obstacle = -1;
  int feature = 0;
  Vec3 normal = Vec3::UnitZ();
};

/// What the obstacle contact code did in a run (diagnostics for reports).
struct ObstacleCounters {
  long long contacts = 0;            ///< particle-obstacle contacts resolved (impulse applied)
  long long separating = 0;          ///< contacts found while the particle already moved away (no impulse)
  long long resting_corrections = 0; ///< resting particles put back on their feature at a step's end
  long long guard_corrections = 0;   ///< particles found inside a sphere or box at a step's end, pushed out
};

class ObstacleContacts {
 public:
  /// Keeps a reference to `obstacles` (which must outlive this object).
  ObstacleContacts(const std::vector<Obstacle>& obstacles, std::size_t n_particles);
  /// The sides of mesh triangles the particles start on; `a0` are their free accelerations at
  /// t = 0, which break ties for a particle on a triangle's plane (as for planes).
  void init_sides(const Particles& p, const std::vector<Vec3>& a0);

  bool empty() const { return obstacles_->empty(); }
  ObstaclePoses& poses() { return poses_; }

  /// True when some free particle moving x0 -> x1 over [poses' start, t1] hits an obstacle.
  bool any_hit(double t1, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, const Particles& p);
  /// Each free particle's earliest obstacle hit over [poses' start, t1], in particle order.
  void collect(double t1, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, const Particles& p,
               std::vector<ObstacleHit>& hits);
  /// Places h's particle where its path reaches the surface, on the pose at t1, and applies
  /// eq. 9 relative to the surface; a static contact starts resting. Returns the branch, or
  /// nothing when the particle was already separating.
  std::optional<ContactKind> resolve(const ObstacleHit& h, double t1, const std::vector<Vec3>& x0, Particles& p,
                                     const ContactSettings& settings);
  /// Mesh sides after the interval ended at t1 with the particles at x (a particle strictly on
  /// the other side of a triangle's plane without a hit went round it).
  void update_sides(double t1, const std::vector<Vec3>& x);

  /// Start of a step at time t: resting contacts released or kept (placed back on their feature,
  /// friction applied); `a_free` are the free accelerations at t.
  void begin_step(double t, Particles& p, const std::vector<Vec3>& a_free, const ContactSettings& settings);
  /// The resting contacts cancel the part of a that pushes into their obstacle.
  void cancel_resting(std::vector<Vec3>& a) const;
  /// End of a step at time t: resting particles that drifted inside by rounding are put back on
  /// their feature; any free particle found strictly inside a sphere or box (only possible when
  /// the event cap was reached, or with overlapping obstacles) is pushed out to the nearest
  /// surface point and its inward relative velocity cancelled. Counted in counters().
  void end_step(double t, Particles& p);

  const std::vector<ObstacleRest>& resting() const { return resting_; }
  /// Relative height above its surface at which a resting particle counts as lifted off (2^-40:
  /// about 4000 times a placement's rounding).
  static constexpr double kLiftTolerance = 0x1p-40;
  const ObstacleCounters& counters() const { return counters_; }

 private:
  std::size_t slot(std::size_t i, std::size_t k, int feature) const;
  ObstacleHit earliest_hit(std::size_t i, const Vec3& x0, const Vec3& x1);
  void place_on_feature(std::size_t i, std::size_t k, int feature, const ObstaclePose& pose, Vec3& x,
                        Vec3& normal) const;
  Vec3 surface_velocity(std::size_t k, int feature, const ObstaclePose& pose, const Vec3& x) const;
  bool keep_resting(const ObstacleRest& r, const ObstaclePose& pose, const Particles& p, const Vec3& a) const;

  const std::vector<Obstacle>* obstacles_;
  ObstaclePoses poses_;
  std::vector<std::size_t> offset_, stride_;  // per obstacle: first slot, slots per particle
  std::vector<std::int8_t> side_;             // mesh triangles: remembered side per (particle, triangle)
  std::vector<std::uint8_t> rest_flag_;       // per slot: a resting contact exists
  std::vector<ObstacleRest> resting_, kept_;
  ObstacleCounters counters_;
};

}  // namespace tecido
