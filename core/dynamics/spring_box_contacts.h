#pragma once
/// Springs against boxes (scene key "edge_contacts"): the contact the seed's engine lacks. In its
/// figs. 10-13 the springs between particles resting on a block and particles hanging beside it
/// cut through the block's edge, which no particle-face test can see. With edge contacts on, no
/// spring ends a step (or an interval of the contact loop) cutting through a box.
///
/// Detection, over an interval of the contact loop, in the box's frame (each spring end moving
/// linearly from its place at the start pose to its place at the end pose, as for particles): a
/// spring hits a box when it cuts through it at the end (it enters the open box,
/// segment_box.h), or when, over the interval, it touched one of the box's 12 edges (core's
/// continuous edge-edge test, ccd/ccd.h, zero false negatives) while its line went from one side of
/// the edge's line to the other (exact orient3d signs at the two ends): a spring that swept
/// through a corner of the box within the interval. That second test runs only for motions of
/// more than kSweep of the spring's length and the box's thickness.
///
/// Response (our choice; the seed has none), at the end of the bisected bracket, where the spring
/// has just begun to cut: the separating axis with the smallest overlap
/// (segment_box_separation.h) gives the normal n and a point p = (1 - a) x_i + a x_j of the
/// spring (the deepest point for an edge's normal). The spring is moved so that p goes out along
/// n by the overlap plus kGap spring lengths, the ends moved as in Bridson, Fedkiw and Anderson
/// 2002, section 7.1: dx_i = (1 - a) w_i D n, dx_j = a w_j D n, W = (1 - a)^2 w_i + a^2 w_j,
/// D = move / W (w: inverse masses), repeated (up to kSweeps) while it still cuts. Then eq. 9 on
/// p's velocity relative to the box's surface: the elastic branch mirrors v_p . n scaled by the
/// box's elasticity (or the ends' k weighted by (1 - a, a)), the static branch cancels it; the
/// impulse is shared the same way. No friction. A static contact rests, position-based: the
/// spring is not tested during the next steps; any spring found cutting a box at the end of an
/// interval or a step (resting, or moved there by another contact's placement) is moved out and
/// its inward velocity at p cancelled (counted); at each step's start a resting spring's p gets
/// no normal velocity (Gauss-Seidel over springs sharing particles) or, when it moves away faster
/// than the static threshold or lies more than kLift spring lengths off the box, is released.
#include "core/dynamics/obstacle_poses.h"
#include "core/dynamics/particles.h"
#include "core/dynamics/plane_contact.h"
#include "core/dynamics/spring.h"
#include "core/geometry/obstacle.h"

#include <cstdint>
#include <vector>

namespace tecido {

/// A spring cutting (or sweeping through) a box over the interval.
struct SpringBoxHit {
  int spring = -1;
  int obstacle = -1;
};

struct SpringBoxCounters {
  long long contacts = 0;      ///< contacts resolved with an impulse
  long long separating = 0;    ///< found while already moving away (moved out, no impulse)
  long long moved_out = 0;     ///< springs found cutting at an interval's or a step's end, moved out
  long long unresolved = 0;    ///< springs still cutting after kSweeps passes (should stay 0)
};

class SpringBoxContacts {
 public:
  /// Every box of `obstacles` against every spring with a free end; empty unless `enabled`.
  /// Keeps a reference to `obstacles`.
  SpringBoxContacts(const std::vector<Obstacle>& obstacles, const std::vector<Spring>& springs,
                    const std::vector<std::uint8_t>& pinned, bool enabled);
  bool empty() const { return pairs_.empty(); }

  bool any_hit(const ObstaclePoses& poses, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1);
  void collect(const ObstaclePoses& poses, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
               std::vector<SpringBoxHit>& hits) const;
  /// Moves each hit spring out of its box (end poses) and applies eq. 9 at its contact point.
  void resolve(const std::vector<SpringBoxHit>& hits, const ObstaclePoses& poses, Particles& p,
               const ContactSettings& settings);
  /// End of an interval or a step (end poses): every spring cutting a box is moved out and its
  /// inward velocity at the contact point cancelled.
  void move_out_all(const ObstaclePoses& poses, Particles& p);
  /// Start of a step (start poses): resting springs kept (no normal velocity) or released.
  void begin_step(const ObstaclePoses& poses, Particles& p, const ContactSettings& settings);

  const SpringBoxCounters& counters() const { return counters_; }
  std::size_t resting_count() const { return resting_.size(); }

  static constexpr double kGap = 1e-9;   ///< clearance a moved spring gets, in spring lengths
  static constexpr double kLift = 1e-4;  ///< a resting spring farther than this (spring lengths) is released
  static constexpr int kSweeps = 16;     ///< passes of move_out_all / resolve's separation
  /// The sweep test runs when an end moves (relative to the box) more than this fraction of the
  /// spring's length and of the box's thickness over the interval; a smaller motion can only
  /// graze a corner of the box and leave it within the interval (the test at the interval's end
  /// still holds).
  static constexpr double kSweep = 0.1;

 private:
  struct Pair {
    int spring;  ///< index into springs_
    int box;     ///< obstacle index
  };
  /// Moves spring s out of box k if it cuts it; returns whether it did, with the contact frame.
  bool move_out(std::size_t s, std::size_t k, const ObstaclePose& pose, Particles& p, Vec3& n, double& a) const;
  /// eq. 9 (static when `static_only`) on the contact point's velocity relative to box k.
  bool respond(std::size_t s, std::size_t k, const ObstaclePose& pose, Particles& p, const Vec3& n, double a,
               const ContactSettings& settings, bool static_only);
  bool hit(std::size_t q, const ObstaclePoses& poses, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) const;

  const std::vector<Obstacle>* obstacles_;
  std::vector<Spring> springs_;
  std::vector<Pair> pairs_;              // every (spring, box)
  std::vector<std::uint8_t> rest_flag_;  // per pair
  std::vector<std::size_t> resting_, kept_;
  SpringBoxCounters counters_;
};

}  // namespace tecido
