#pragma once
/// One simulation of a Scene, stepped the way the seed's engine does (section 3.1.1):
///   1. forces are gathered into accelerations (force_model.h);
///   2. the integrator advances every particle by the step;
///   3. each particle's motion p1 -> p2 is tested against every bounded plane; on a hit the
///      step is bisected (fig. 8) to the time of contact, the impulse of eq. 9 is applied at
///      that time, and the rest of the step is integrated again (repeatedly: several contacts
///      in one step, e.g. a particle in the corner of two planes, are handled in time order).
/// A static contact (|vn| <= threshold) becomes a resting contact: while the particle stays
/// inside the rectangle and the free acceleration pushes it into the plane, the plane cancels
/// that normal component (the seed's "levíssima força na direção da normal") and friction acts
/// on vt once per step. A particle remembers which side of each plane it is on, so it can
/// never pass through the rectangle, whatever the step size.
/// Obstacles (spheres, boxes, meshes, static or moving; obstacle_contacts.h) take part in the
/// same event loop: one bisection finds the earliest contact of any kind, every particle's
/// earliest contact (plane or obstacle) up to that time is resolved, and the rest of the step
/// is integrated again. With edge_contacts, springs against boxes (spring_box_contacts.h) and
/// against mesh edges (edge_contacts.h) join the same loop. A scene without obstacles steps
/// exactly as before (bit for bit).
#include "core/dynamics/edge_contacts.h"
#include "core/dynamics/integrator.h"
#include "core/dynamics/obstacle_contacts.h"
#include "core/dynamics/spring_box_contacts.h"
#include "core/scene/scene.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tecido {

/// Where and why a run stopped being finite.
struct Instability {
  long long step = 0;      ///< 1-based index of the step that produced the bad value
  int particle = -1;
  std::string quantity;    ///< "position" or "velocity"
};

struct ContactCounters {
  long long events = 0;         ///< bisected contact events
  long long elastic = 0;        ///< particle contacts answered by the elastic branch
  long long static_contacts = 0;///< ... by the static branch
  long long cap_hits = 0;       ///< steps whose event cap was reached (contacts then resolved without bisection)
  long long bisections = 0;     ///< integrator calls spent bisecting
};

/// One resolved particle-plane or particle-obstacle contact, when the simulation logs them.
struct ContactEvent {
  long long step = 0;   ///< 1-based step during which the contact happened
  double time = 0.0;    ///< time of contact [s] (upper end of the bisection bracket)
  int particle = -1;
  int plane = -1;       ///< -1 for an obstacle contact
  ContactKind kind = ContactKind::Elastic;
  Vec3 velocity_before = Vec3::Zero();
  Vec3 velocity_after = Vec3::Zero();
  int obstacle = -1;    ///< -1 for a plane contact
  int feature = -1;     ///< the obstacle's box face or mesh triangle (0 for a sphere)
};

class Simulation {
 public:
  explicit Simulation(const Scene& scene);

  /// Advances one step of scene.dt. Returns false (and records instability()) when a position
  /// or velocity became NaN or infinite; later calls do nothing and return false.
  bool step();
  /// Runs up to n steps; calls on_frame after each step (if set). Stops at the first unstable step.
  bool run(long long n, const std::function<void(const Simulation&)>& on_frame = {});

  const Particles& particles() const { return p_; }
  Particles& mutable_particles() { return p_; }
  const Scene& scene() const { return scene_; }
  double time() const { return static_cast<double>(step_) * scene_.dt; }
  long long steps_done() const { return step_; }
  const std::optional<Instability>& instability() const { return instability_; }
  const ContactCounters& contacts() const { return counters_; }
  /// The (particle, plane) pairs in resting contact now.
  const std::vector<std::pair<int, int>>& resting_contacts() const { return resting_; }
  /// The particle-obstacle contacts: resting contacts now, counters.
  const ObstacleContacts& obstacle_contacts() const { return obstacles_; }
  /// The spring-edge contacts of meshes and the spring-box contacts (empty unless the scene asks
  /// for edge_contacts).
  const EdgeContacts& edge_contacts() const { return edges_; }
  const SpringBoxContacts& spring_box_contacts() const { return spring_boxes_; }
  double bisection_tolerance() const { return tol_; }
  /// Keep a log of every contact (off by default; the log grows with the run).
  void set_log_contacts(bool on) { log_contacts_ = on; }
  const std::vector<ContactEvent>& contact_log() const { return contact_log_; }

  /// Hook run after each step's plane contacts (e.g. cloth self-collision response).
  /// It may change positions and velocities.
  std::function<void(Simulation&)> post_step;

 private:
  struct Hit {
    int particle;
    int plane;
    double t;  // fraction along the particle's segment
  };
  void accelerations(double t, const std::vector<Vec3>& x, const std::vector<Vec3>& v, std::vector<Vec3>& a);
  bool any_hit(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1);
  /// Planes, then obstacles over [loop start, t1].
  bool any_contact(double t1, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1);
  void collect_hits(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, std::vector<Hit>& hits);
  /// Resolves every particle's earliest contact (plane or obstacle) over [loop start, t1].
  void resolve_contacts(double t1, const std::vector<Vec3>& x0);
  void update_sides(const std::vector<Vec3>& x);
  void update_obstacle_sides(double t1);
  void begin_step_resting(double t);
  void resolve_hit(const Hit& h, const std::vector<Vec3>& x0, double t_contact);
  void resolve_obstacle_hit(const ObstacleHit& h, const std::vector<Vec3>& x0, double t_contact);
  void place_on_plane(int i, int p);
  bool check_finite();

  Scene scene_;
  Particles p_;
  PackedSprings springs_;  // scene_.forces.springs compiled for the force loop
  Integrator integ_;
  AccelerationFn accel_;
  double tol_ = 0.0;
  long long step_ = 0;
  std::optional<Instability> instability_;
  ContactCounters counters_;
  std::size_t n_planes_ = 0;
  std::vector<std::int8_t> side_;           // remembered side per (particle, plane), +1 / -1
  std::vector<std::uint8_t> resting_flag_;  // per (particle, plane)
  std::vector<std::pair<int, int>> resting_;
  std::vector<std::pair<int, int>> resting_scratch_;  // the next step's resting_, swapped in
  std::vector<Vec3> x0_, v0_, xm_, vm_, a_free_;
  std::vector<Hit> hits_;
  ObstacleContacts obstacles_;
  std::vector<ObstacleHit> obstacle_hits_;
  EdgeContacts edges_;
  std::vector<EdgeHit> edge_hits_;
  SpringBoxContacts spring_boxes_;
  std::vector<SpringBoxHit> spring_box_hits_;
  bool log_contacts_ = false;
  std::vector<ContactEvent> contact_log_;
};

}  // namespace tecido
