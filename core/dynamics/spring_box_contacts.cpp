#include "core/dynamics/spring_box_contacts.h"

#include "core/geometry/box_mesh.h"
#include "core/geometry/ccd/ccd.h"
#include "core/geometry/obstacle_pose.h"
#include "core/geometry/orient_predicates.h"
#include "core/geometry/segment_box.h"
#include "core/geometry/segment_box_separation.h"

#include <algorithm>
#include <cmath>

namespace tecido {

SpringBoxContacts::SpringBoxContacts(const std::vector<Obstacle>& obstacles, const std::vector<Spring>& springs,
                                     const std::vector<std::uint8_t>& pinned, bool enabled)
    : obstacles_(&obstacles) {
  if (!enabled) return;
  for (const Spring& sp : springs)
    if (!pinned[static_cast<std::size_t>(sp.i)] || !pinned[static_cast<std::size_t>(sp.j)]) springs_.push_back(sp);
  for (std::size_t s = 0; s < springs_.size(); ++s)
    for (std::size_t k = 0; k < obstacles.size(); ++k)
      if (obstacles[k].kind == ObstacleKind::Box) pairs_.push_back(Pair{static_cast<int>(s), static_cast<int>(k)});
  rest_flag_.assign(pairs_.size(), 0);
}

bool SpringBoxContacts::hit(std::size_t q, const ObstaclePoses& poses, const std::vector<Vec3>& x0,
                            const std::vector<Vec3>& x1) const {
  const Spring& sp = springs_[static_cast<std::size_t>(pairs_[q].spring)];
  const std::size_t k = static_cast<std::size_t>(pairs_[q].box);
  const Vec3& h = (*obstacles_)[k].half_extents;
  const ObstaclePose &a = poses.start(k), &b = poses.end(k);
  // In the box's frame, each end moving linearly from its place at the start pose to its place
  // at the end pose (as for particles, segment_box.h), the box and its edges still.
  const Vec3 qi1 = b.to_local(x1[sp.i]), qj1 = b.to_local(x1[sp.j]);
  if (segment_enters_box(qi1, qj1, h).hit) return true;
  const Vec3 qi0 = a.to_local(x0[sp.i]), qj0 = a.to_local(x0[sp.j]);
  // Swept through a corner of the box and out again? Only a motion of more than kSweep of the
  // spring's length and of the box's thickness can carry a spring from one side of the box's
  // edge to the other without it cutting the box at the interval's end.
  const double motion = std::max((qi1 - qi0).norm(), (qj1 - qj0).norm());
  if (!(motion > kSweep * std::min((qj1 - qi1).norm(), 2.0 * h.minCoeff()))) return false;
  const Vec3 lo = qi0.cwiseMin(qj0).cwiseMin(qi1).cwiseMin(qj1), hi = qi0.cwiseMax(qj0).cwiseMax(qi1).cwiseMax(qj1);
  if ((lo.array() > h.array()).any() || (hi.array() < -h.array()).any()) return false;
  const auto corners = box_corners(h);
  for (const auto& e : kBoxEdges) {
    const Vec3 &e0 = corners[e[0]], &e1 = corners[e[1]];
    const int s0 = orient3d_sign(qi0, qj0, e0, e1), s1 = orient3d_sign(qi1, qj1, e0, e1);
    if (s0 * s1 >= 0) continue;  // its line did not change sides of the edge's line
    CcdQuery cq;
    cq.kind = CcdKind::EdgeEdge;
    cq.x0 = {qi0, qj0, e0, e1};
    cq.x1 = {qi1, qj1, e0, e1};
    if (ccd(cq).hit) return true;
  }
  return false;
}

bool SpringBoxContacts::any_hit(const ObstaclePoses& poses, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  for (std::size_t q = 0; q < pairs_.size(); ++q)
    if (!rest_flag_[q] && hit(q, poses, x0, x1)) return true;
  return false;
}

void SpringBoxContacts::collect(const ObstaclePoses& poses, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                                std::vector<SpringBoxHit>& hits) const {
  hits.clear();
  for (std::size_t q = 0; q < pairs_.size(); ++q)
    if (!rest_flag_[q] && hit(q, poses, x0, x1)) hits.push_back(SpringBoxHit{pairs_[q].spring, pairs_[q].box});
}

bool SpringBoxContacts::move_out(std::size_t s, std::size_t k, const ObstaclePose& pose, Particles& p, Vec3& n,
                                 double& a) const {
  const Spring& sp = springs_[s];
  const Obstacle& o = (*obstacles_)[k];
  bool moved = false;
  for (int sweep = 0; sweep < kSweeps; ++sweep) {
    const Vec3 qi = pose.to_local(p.x[sp.i]), qj = pose.to_local(p.x[sp.j]);
    if (!segment_enters_box(qi, qj, o.half_extents).hit) return moved;  // the cheap test first
    const SegmentBoxSeparation sep = segment_box_separation(qi, qj, o.half_extents);
    if (!sep.cuts) return moved;
    a = sep.s;
    n = pose.rotation * sep.normal;
    const double wi = p.inv_mass[sp.i], wj = p.inv_mass[sp.j];
    const double w = (1 - a) * (1 - a) * wi + a * a * wj;
    if (!(w > 0.0)) return moved;
    // Past the overlap by the gap, and by a few ulps of the coordinates (rounding of the frame).
    const double scale = std::max({p.x[sp.i].cwiseAbs().maxCoeff(), p.x[sp.j].cwiseAbs().maxCoeff(), pose.center.cwiseAbs().maxCoeff()});
    const double move = sep.overlap + kGap * (p.x[sp.j] - p.x[sp.i]).norm() + 0x1p-48 * scale;
    p.x[sp.i] += (1 - a) * wi * move / w * n;
    p.x[sp.j] += a * wj * move / w * n;
    moved = true;
  }
  return moved;
}

bool SpringBoxContacts::respond(std::size_t s, std::size_t k, const ObstaclePose& pose, Particles& p, const Vec3& n,
                                double a, const ContactSettings& settings, bool static_only) {
  const Spring& sp = springs_[s];
  const Obstacle& o = (*obstacles_)[k];
  const double wi = p.inv_mass[sp.i], wj = p.inv_mass[sp.j];
  const double w = (1 - a) * (1 - a) * wi + a * a * wj;
  if (!(w > 0.0)) return false;
  const Vec3 point = p.x[sp.i] + a * (p.x[sp.j] - p.x[sp.i]);
  const double vn = n.dot((1 - a) * p.v[sp.i] + a * p.v[sp.j] - obstacle_surface_velocity(o, pose, point));
  if (vn > 0.0) return false;
  const double k_el = o.elasticity ? *o.elasticity : (1 - a) * p.elasticity[sp.i] + a * p.elasticity[sp.j];
  const bool elastic = !static_only && std::abs(vn) > settings.static_threshold;
  const double j = (elastic ? -(1.0 + k_el) * vn : -vn) / w;
  p.v[sp.i] += (1 - a) * wi * j * n;
  p.v[sp.j] += a * wj * j * n;
  return !elastic;
}

void SpringBoxContacts::resolve(const std::vector<SpringBoxHit>& hits, const ObstaclePoses& poses, Particles& p,
                                const ContactSettings& settings) {
  const std::size_t n_boxes = pairs_.size() / std::max<std::size_t>(springs_.size(), 1);
  for (const SpringBoxHit& h : hits) {
    const std::size_t s = static_cast<std::size_t>(h.spring), k = static_cast<std::size_t>(h.obstacle);
    const ObstaclePose& pose = poses.end(k);
    Vec3 n;
    double a = 0.5;
    if (!move_out(s, k, pose, p, n, a)) {
      ++counters_.separating;  // swept through and out again within the bracket: nothing to undo
      continue;
    }
    const Spring& sp = springs_[s];
    const double vn_before = n.dot((1 - a) * p.v[sp.i] + a * p.v[sp.j]);
    const bool stat = respond(s, k, pose, p, n, a, settings, false);
    if (vn_before > 0.0) {
      ++counters_.separating;
      continue;
    }
    ++counters_.contacts;
    if (!stat) continue;
    // The pair's index: pairs_ holds every box for spring s, in obstacle order.
    for (std::size_t q = s * n_boxes; q < (s + 1) * n_boxes; ++q)
      if (static_cast<std::size_t>(pairs_[q].box) == k && !rest_flag_[q]) {
        rest_flag_[q] = 1;
        resting_.push_back(q);
      }
  }
  move_out_all(poses, p);
}

void SpringBoxContacts::move_out_all(const ObstaclePoses& poses, Particles& p) {
  for (int sweep = 0; sweep < kSweeps; ++sweep) {
    bool moved = false;
    for (const Pair& pr : pairs_) {
      const std::size_t s = static_cast<std::size_t>(pr.spring), k = static_cast<std::size_t>(pr.box);
      Vec3 n;
      double a = 0.5;
      if (!move_out(s, k, poses.end(k), p, n, a)) continue;
      respond(s, k, poses.end(k), p, n, a, ContactSettings{}, true);
      ++counters_.moved_out;
      moved = true;
    }
    if (!moved) return;
  }
  for (const Pair& pr : pairs_) {
    const Spring& sp = springs_[static_cast<std::size_t>(pr.spring)];
    const ObstaclePose& pose = poses.end(static_cast<std::size_t>(pr.box));
    if (segment_enters_box(pose.to_local(p.x[sp.i]), pose.to_local(p.x[sp.j]),
                           (*obstacles_)[static_cast<std::size_t>(pr.box)].half_extents).hit)
      ++counters_.unresolved;
  }
}

void SpringBoxContacts::begin_step(const ObstaclePoses& poses, Particles& p, const ContactSettings& settings) {
  struct Held {
    std::size_t s, k;
    Vec3 n;
    double a, w;
    Vec3 u;
  };
  std::vector<Held> held;
  kept_.clear();
  for (std::size_t q : resting_) {
    const std::size_t s = static_cast<std::size_t>(pairs_[q].spring), k = static_cast<std::size_t>(pairs_[q].box);
    const Spring& sp = springs_[s];
    const Obstacle& o = (*obstacles_)[k];
    const ObstaclePose& pose = poses.start(k);
    const SegmentBoxSeparation sep =
        segment_box_separation(pose.to_local(p.x[sp.i]), pose.to_local(p.x[sp.j]), o.half_extents);
    const double a = sep.s, wi = p.inv_mass[sp.i], wj = p.inv_mass[sp.j];
    const double w = (1 - a) * (1 - a) * wi + a * a * wj;
    const Vec3 n = pose.rotation * sep.normal;
    const Vec3 point = p.x[sp.i] + a * (p.x[sp.j] - p.x[sp.i]);
    const Vec3 u = obstacle_surface_velocity(o, pose, point);
    const double vn = n.dot((1 - a) * p.v[sp.i] + a * p.v[sp.j] - u);
    if (!(w > 0.0) || sep.clearance > kLift * (p.x[sp.j] - p.x[sp.i]).norm() || vn > settings.static_threshold) {
      rest_flag_[q] = 0;
      continue;
    }
    kept_.push_back(q);
    held.push_back(Held{s, k, n, a, w, u});
  }
  resting_.swap(kept_);
  // Static contacts: no normal velocity at any contact point (Gauss-Seidel: they share particles).
  for (int sweep = 0; sweep < 4; ++sweep)
    for (const Held& h : held) {
      const Spring& sp = springs_[h.s];
      const double vn = h.n.dot((1 - h.a) * p.v[sp.i] + h.a * p.v[sp.j] - h.u);
      p.v[sp.i] -= (1 - h.a) * p.inv_mass[sp.i] * vn / h.w * h.n;
      p.v[sp.j] -= h.a * p.inv_mass[sp.j] * vn / h.w * h.n;
    }
}

}  // namespace tecido
