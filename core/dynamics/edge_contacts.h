#pragma once
/// Springs against mesh obstacles' edges (scene key "edge_contacts"; boxes have their own,
/// spring_box_contacts.h, since a box has an inside). A mesh, open or closed, has no inside to
/// keep a spring out of, only edges a spring must not cross: its feature edges (mesh_edges.h, at
/// t = 0); a sphere has none (its chords are reported, not prevented). For
/// every (spring, edge) pair the engine remembers on which side of the edge's line the spring's
/// line passes (exact: orient3d_sign(x_i, x_j, e0, e1)), as for planes; over an interval of the
/// contact loop a pair is tested when the spring does not end strictly on that side (and their
/// swept boxes meet), by core's continuous edge-edge test (ccd/ccd.h, zero false negatives) with the
/// spring's ends moving x0 -> x1 and the edge from its start to its end pose. A side changes
/// without a contact only when the lines passed each other beyond the segments' ends.
///
/// Response (our choice; the seed has none): at the closest points of the spring (parameter a
/// along i -> j) and the edge, with n the unit normal of the two lines pointing to the spring's
/// side, the contact point p = (1 - a) x_i + a x_j is treated as a particle: eq. 9 on its
/// velocity relative to the edge, v_p . n, with the obstacle's elasticity, or else the ends' k
/// weighted by (1 - a, a), and no friction. The impulse J n at p is shared as in Bridson, Fedkiw
/// and Anderson 2002 (section 7.1): dv_i = (1 - a) w_i J n, dv_j = a w_j J n, w the inverse masses,
/// J = dv_n / ((1 - a)^2 w_i + a^2 w_j), which changes v_p . n by exactly dv_n. Positions are moved
/// the same way until the contact point is kEdgeGap spring lengths past the edge's line, on its
/// side; a spring that meets several edges at once (near a corner) is moved for each. A
/// static contact rests, position-based: the pair is not tested during the step; at the step's
/// end a spring found through its edge is put back on its side (counted), and at the next step's
/// start its contact point's normal velocity is cancelled (eq. 9's static branch, shared the same
/// way; Gauss-Seidel sweeps over contacts sharing particles), until the free acceleration pulls
/// away, the contact point moves away faster than the static threshold or is lifted off the edge
/// by more than kLift spring lengths, or the closest points leave the segments. (Cancelling the
/// contact point's acceleration during the step instead, as planes do for particles, was tried:
/// with many contacts sharing particles and the particles' own face contacts it pumped energy into
/// a draped cloth; the position-based rest only ever removes it.)
#include "core/dynamics/obstacle_poses.h"
#include "core/dynamics/particles.h"
#include "core/dynamics/plane_contact.h"
#include "core/dynamics/spring.h"
#include "core/geometry/obstacle.h"

#include <array>
#include <cstdint>
#include <vector>

namespace tecido {

/// A spring's contact with an obstacle edge over the interval (every edge it touches is one:
/// a spring is moved back rather than rewound, so near a corner it may meet several at once).
struct EdgeHit {
  int spring = -1;
  int edge = -1;   ///< index into EdgeContacts::edges()
  double s = 2.0;  ///< fraction of the interval
};

/// An obstacle edge: vertex indices of mesh obstacle `obstacle`.
struct ObstacleEdge {
  int obstacle = -1;
  std::array<int, 2> ends{};
};

struct EdgeCounters {
  long long contacts = 0;             ///< spring-edge contacts resolved (impulse applied)
  long long separating = 0;           ///< found while already separating (no impulse)
  long long resting_corrections = 0;  ///< resting springs put back on their side at a step's end
  long long separation_sweeps = 0;    ///< extra passes of separate() that moved a spring
  long long moved_through = 0;        ///< springs another contact's placement moved through an edge, put back
};

class EdgeContacts {
 public:
  /// An axis-aligned box (swept boxes of the broad phase).
  struct Box3 {
    Vec3 lo, hi;
    bool overlaps(const Box3& b) const {
      return lo.x() <= b.hi.x() && b.lo.x() <= hi.x() && lo.y() <= b.hi.y() && b.lo.y() <= hi.y() &&
             lo.z() <= b.hi.z() && b.lo.z() <= hi.z();
    }
  };
  /// Every feature edge of every mesh obstacle, every spring with a free end (`pinned` per particle); empty
  /// when `enabled` is false. Keeps a reference to `obstacles`.
  EdgeContacts(const std::vector<Obstacle>& obstacles, const std::vector<Spring>& springs,
               const std::vector<std::uint8_t>& pinned, bool enabled);
  bool empty() const { return edges_.empty() || springs_.empty(); }
  const std::vector<ObstacleEdge>& edges() const { return edges_; }

  /// Sides at t = 0 from the particles' positions (poses at their start time).
  void init_sides(const ObstaclePoses& poses, const Particles& p);
  bool any_hit(const ObstaclePoses& poses, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1);
  /// Every (spring, edge) contact over the interval, in spring then edge order.
  void collect(const ObstaclePoses& poses, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
               std::vector<EdgeHit>& hits);
  /// Moves the spring back to its side of the edge (end poses) and applies the impulse above.
  void resolve(const EdgeHit& h, const ObstaclePoses& poses, Particles& p, const ContactSettings& settings);
  /// After resolving `hits` one by one, the resting contacts' normal velocities are cancelled
  /// again (settle_resting), and a spring moved back by one contact that another, sharing a
  /// particle, pushed through its own edge again is put back: up to kSeparationSweeps passes
  /// (Gauss-Seidel).
  void separate(const std::vector<EdgeHit>& hits, const ObstaclePoses& poses, Particles& p);
  static constexpr int kSeparationSweeps = 16;
  /// How far past the edge's line a spring is put back, in spring lengths: enough that the
  /// segment is clear of the obstacle beyond rounding (a spring exactly on a box edge would
  /// touch the box's inside by rounding), too small to see.
  static constexpr double kEdgeGap = 1e-9;
  /// A resting spring lifted off its edge by more than this many spring lengths is released (its
  /// neighbours' contacts move it by about a step's motion; far less than any real separation).
  static constexpr double kLift = 1e-4;
  /// A spring found through an edge within this many spring lengths of it at an interval's end was
  /// moved there (update_sides), not gone round it.
  static constexpr double kNear = 0.05;
  /// Gauss-Seidel sweeps over the resting contacts when their normal velocities and accelerations
  /// are cancelled (contacts sharing a particle disturb each other).
  static constexpr int kRestingSweeps = 4;
  /// At an interval's end (end poses): a pair strictly on the other side of its edge is either put
  /// back (a resting spring that sank through during the step, or one that another contact's
  /// placement moved through: moved_through) or, having gone round the edge, has its side flipped. Repeated while it put any back (up to
  /// kSeparationSweeps passes).
  void update_sides(const ObstaclePoses& poses, Particles& p);

  /// Resting contacts at the start of a step (start poses; `a_free` the free accelerations).
  void begin_step(const ObstaclePoses& poses, Particles& p, const std::vector<Vec3>& a_free,
                  const ContactSettings& settings);
  /// The step's end (end poses): update_sides once more, after everything else moved particles.
  void end_step(const ObstaclePoses& poses, Particles& p);

  const EdgeCounters& counters() const { return counters_; }
  std::size_t resting_count() const { return resting_.size(); }

 private:
  struct Rest {
    std::size_t pair;  ///< spring * edges + edge
    double a;          ///< parameter along the spring
    Vec3 normal;
    Vec3 point;        ///< the edge's closest point
    double w;          ///< (1 - a)^2 w_i + a^2 w_j
    Vec3 surface_velocity;
  };
  std::array<Vec3, 2> edge_at(const ObstaclePose& pose, std::size_t e) const;
  int side_now(const ObstaclePose& pose, std::size_t s, std::size_t e, const std::vector<Vec3>& x) const;
  /// The edges spring s touches over the prepared interval (appended to *hits); with
  /// hits == nullptr, whether there is one (stops at the first).
  bool hits_of(std::size_t s, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
               std::vector<EdgeHit>* hits) const;
  /// Every edge's ends at the interval's start and end poses, and their swept boxes.
  void prepare(const ObstaclePoses& poses);
  bool contact_frame(std::size_t s, std::size_t e, const ObstaclePose& pose, const Particles& p, double& a,
                     Vec3& q, Vec3& n) const;
  void push_out(std::size_t s, std::size_t e, const ObstaclePose& pose, Particles& p) const;
  /// Whether spring s, found on the other side of edge e at the interval's end (prepared ends), was
  /// moved through it rather than gone round it: its closest point to the closed edge (an end of
  /// the edge included: a corner) lies inside the spring, within kNear spring lengths.
  bool moved_through(std::size_t s, std::size_t e, const std::vector<Vec3>& x) const;
  /// kRestingSweeps Gauss-Seidel passes cancelling every resting contact point's normal velocity.
  void settle_resting(Particles& p) const;

  const std::vector<Obstacle>* obstacles_;
  std::vector<ObstacleEdge> edges_;
  std::vector<Spring> springs_;       // springs with at least one free end
  std::vector<std::int8_t> side_;     // per (spring, edge)
  std::vector<std::uint8_t> rest_flag_;
  std::vector<Rest> resting_, kept_;
  std::vector<std::array<Vec3, 2>> start_, end_;  // prepared edge ends
  std::vector<Box3> swept_;                      // prepared swept boxes
  Box3 all_;                                     // their union
  EdgeCounters counters_;
};

}  // namespace tecido
