#include "core/dynamics/edge_contacts.h"

#include "core/geometry/ccd/ccd.h"
#include "core/geometry/closest_points.h"
#include "core/geometry/mesh_edges.h"
#include "core/geometry/obstacle_pose.h"
#include "core/geometry/orient_predicates.h"

#include <algorithm>
#include <cmath>

namespace tecido {

namespace {

EdgeContacts::Box3 box_of(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return EdgeContacts::Box3{a.cwiseMin(b).cwiseMin(c).cwiseMin(d), a.cwiseMax(b).cwiseMax(c).cwiseMax(d)};
}

}  // namespace

EdgeContacts::EdgeContacts(const std::vector<Obstacle>& obstacles, const std::vector<Spring>& springs,
                           const std::vector<std::uint8_t>& pinned, bool enabled)
    : obstacles_(&obstacles) {
  if (!enabled) return;
  for (std::size_t k = 0; k < obstacles.size(); ++k) {
    const Obstacle& o = obstacles[k];
    if (o.kind == ObstacleKind::Mesh)
      for (const auto& e : mesh_feature_edges(o.vertices, o.triangles)) edges_.push_back(ObstacleEdge{static_cast<int>(k), e});
  }
  for (const Spring& sp : springs)
    if (!pinned[static_cast<std::size_t>(sp.i)] || !pinned[static_cast<std::size_t>(sp.j)]) springs_.push_back(sp);
  side_.assign(springs_.size() * edges_.size(), 1);
  rest_flag_.assign(side_.size(), 0);
}

std::array<Vec3, 2> EdgeContacts::edge_at(const ObstaclePose& pose, std::size_t e) const {
  return {pose.vertices[edges_[e].ends[0]], pose.vertices[edges_[e].ends[1]]};
}

void EdgeContacts::prepare(const ObstaclePoses& poses) {
  start_.resize(edges_.size());
  end_.resize(edges_.size());
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const std::size_t k = static_cast<std::size_t>(edges_[e].obstacle);
    start_[e] = edge_at(poses.start(k), e);
    end_[e] = edge_at(poses.end(k), e);
  }
  swept_.resize(edges_.size());
  all_ = Box3{Vec3::Constant(INFINITY), Vec3::Constant(-INFINITY)};
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    swept_[e] = box_of(start_[e][0], start_[e][1], end_[e][0], end_[e][1]);
    all_.lo = all_.lo.cwiseMin(swept_[e].lo);
    all_.hi = all_.hi.cwiseMax(swept_[e].hi);
  }
}

int EdgeContacts::side_now(const ObstaclePose& pose, std::size_t s, std::size_t e, const std::vector<Vec3>& x) const {
  const auto ends = edge_at(pose, e);
  return orient3d_sign(x[springs_[s].i], x[springs_[s].j], ends[0], ends[1]);
}

void EdgeContacts::init_sides(const ObstaclePoses& poses, const Particles& p) {
  for (std::size_t s = 0; s < springs_.size(); ++s)
    for (std::size_t e = 0; e < edges_.size(); ++e) {
      const int side = side_now(poses.start(static_cast<std::size_t>(edges_[e].obstacle)), s, e, p.x);
      side_[s * edges_.size() + e] = static_cast<std::int8_t>(side == 0 ? 1 : side);
    }
}

bool EdgeContacts::hits_of(std::size_t s, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                           std::vector<EdgeHit>* hits) const {
  const Spring& sp = springs_[s];
  const Box3 path = box_of(x0[sp.i], x0[sp.j], x1[sp.i], x1[sp.j]);
  if (!all_.overlaps(path)) return false;
  bool any = false;
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const std::size_t id = s * edges_.size() + e;
    if (rest_flag_[id] || !swept_[e].overlaps(path)) continue;
    const auto &a = start_[e], &b = end_[e];
    if (orient3d_sign(x1[sp.i], x1[sp.j], b[0], b[1]) == side_[id]) continue;  // still strictly on its side
    CcdQuery q;
    q.kind = CcdKind::EdgeEdge;
    q.x0 = {x0[sp.i], x0[sp.j], a[0], a[1]};
    q.x1 = {x1[sp.i], x1[sp.j], b[0], b[1]};
    const CcdAnswer ans = ccd(q);
    if (!ans.hit) continue;
    if (!hits) return true;
    hits->push_back(EdgeHit{static_cast<int>(s), static_cast<int>(e), std::clamp(ans.toi, 0.0, 1.0)});
    any = true;
  }
  return any;
}

bool EdgeContacts::any_hit(const ObstaclePoses& poses, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  prepare(poses);
  for (std::size_t s = 0; s < springs_.size(); ++s)
    if (hits_of(s, x0, x1, nullptr)) return true;
  return false;
}

void EdgeContacts::collect(const ObstaclePoses& poses, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                           std::vector<EdgeHit>& hits) {
  hits.clear();
  prepare(poses);
  for (std::size_t s = 0; s < springs_.size(); ++s) hits_of(s, x0, x1, &hits);
}

bool EdgeContacts::contact_frame(std::size_t s, std::size_t e, const ObstaclePose& pose, const Particles& p, double& a,
                                 Vec3& q, Vec3& n) const {
  const Spring& sp = springs_[s];
  const Vec3 &xi = p.x[sp.i], &xj = p.x[sp.j];
  const auto ed = edge_at(pose, e);
  const Vec2 st = closest_segment_params(xi, xj, ed[0], ed[1]);
  a = st[0];
  q = ed[0] + st[1] * (ed[1] - ed[0]);
  const Vec3 m = (xj - xi).cross(ed[1] - ed[0]);
  const double len = m.norm();
  // orient3d_sign(x_i, x_j, e0, e1) = +1 when the spring's line lies on the -m side of the edge's.
  if (len > 0.0 && std::isfinite(len)) {
    n = -static_cast<double>(side_[s * edges_.size() + e]) * m / len;
    return true;
  }
  const Vec3 d = (xi + a * (xj - xi)) - q;  // parallel lines: along their offset
  if (!(d.norm() > 0.0)) return false;
  n = d.normalized();
  return true;
}

void EdgeContacts::push_out(std::size_t s, std::size_t e, const ObstaclePose& pose, Particles& p) const {
  const Spring& sp = springs_[s];
  const int side = side_[s * edges_.size() + e];
  double a;
  Vec3 q, n;
  if (!contact_frame(s, e, pose, p, a, q, n)) return;
  const double wi = p.inv_mass[sp.i], wj = p.inv_mass[sp.j];
  const double w = (1 - a) * (1 - a) * wi + a * a * wj;
  if (!(w > 0.0)) return;
  const auto ed = edge_at(pose, e);
  const Vec3 contact = p.x[sp.i] + a * (p.x[sp.j] - p.x[sp.i]);
  // Move the contact point along n to kEdgeGap spring lengths past the edge's line, then by
  // doubling ulps until the lines are strictly on their sides (parallel lines: once).
  const double gap = kEdgeGap * (p.x[sp.j] - p.x[sp.i]).norm();
  double delta = std::max(0.0, gap - n.dot(contact - q));
  double step = 0x1p-52 * std::max({p.x[sp.i].cwiseAbs().maxCoeff(), p.x[sp.j].cwiseAbs().maxCoeff(), 1e-300});
  for (int tries = 0; tries < 64; ++tries) {
    if (delta > 0.0) {
      p.x[sp.i] += (1 - a) * wi * delta / w * n;
      p.x[sp.j] += a * wj * delta / w * n;
    }
    const int now = orient3d_sign(p.x[sp.i], p.x[sp.j], ed[0], ed[1]);
    if (now == side || (now == 0 && tries > 0)) return;
    delta = step;
    step *= 2.0;
  }
}

void EdgeContacts::resolve(const EdgeHit& h, const ObstaclePoses& poses, Particles& p,
                           const ContactSettings& settings) {
  const std::size_t s = static_cast<std::size_t>(h.spring), e = static_cast<std::size_t>(h.edge);
  const Spring& sp = springs_[s];
  const std::size_t k = static_cast<std::size_t>(edges_[e].obstacle);
  const Obstacle& o = (*obstacles_)[k];
  const ObstaclePose& pose = poses.end(k);
  push_out(s, e, pose, p);
  double a;
  Vec3 q, n;
  if (!contact_frame(s, e, pose, p, a, q, n)) return;
  const double wi = p.inv_mass[sp.i], wj = p.inv_mass[sp.j];
  const double w = (1 - a) * (1 - a) * wi + a * a * wj;
  if (!(w > 0.0)) return;
  const Vec3 u = obstacle_surface_velocity(o, pose, q);
  const Vec3 rel = (1 - a) * p.v[sp.i] + a * p.v[sp.j] - u;
  const double vn = n.dot(rel);
  if (vn > 0.0) {
    ++counters_.separating;
    return;
  }
  const double k_el = o.elasticity ? *o.elasticity : (1 - a) * p.elasticity[sp.i] + a * p.elasticity[sp.j];
  const bool elastic = std::abs(vn) > settings.static_threshold;
  const double dvn = elastic ? -(1.0 + k_el) * vn : -vn;
  const double j = dvn / w;
  p.v[sp.i] += (1 - a) * wi * j * n;
  p.v[sp.j] += a * wj * j * n;
  ++counters_.contacts;
  const std::size_t id = s * edges_.size() + e;
  if (!elastic && !rest_flag_[id]) {
    rest_flag_[id] = 1;
    resting_.push_back(Rest{id, a, n, q, w, u});
  }
}

void EdgeContacts::separate(const std::vector<EdgeHit>& hits, const ObstaclePoses& poses, Particles& p) {
  if (!hits.empty()) settle_resting(p);
  for (int sweep = 0; sweep < kSeparationSweeps; ++sweep) {
    bool moved = false;
    for (const EdgeHit& h : hits) {
      const std::size_t s = static_cast<std::size_t>(h.spring), e = static_cast<std::size_t>(h.edge);
      const ObstaclePose& pose = poses.end(static_cast<std::size_t>(edges_[e].obstacle));
      if (side_now(pose, s, e, p.x) != -side_[s * edges_.size() + e]) continue;
      push_out(s, e, pose, p);
      moved = true;
    }
    if (!moved) return;
    ++counters_.separation_sweeps;
  }
}

bool EdgeContacts::moved_through(std::size_t s, std::size_t e, const std::vector<Vec3>& x) const {
  const Spring& sp = springs_[s];
  const Vec2 st = closest_segment_params(x[sp.i], x[sp.j], end_[e][0], end_[e][1]);
  const Vec3 d = (x[sp.i] + st[0] * (x[sp.j] - x[sp.i])) - (end_[e][0] + st[1] * (end_[e][1] - end_[e][0]));
  return st[0] > 0.0 && st[0] < 1.0 && d.norm() <= kNear * (x[sp.j] - x[sp.i]).norm();
}

void EdgeContacts::update_sides(const ObstaclePoses& poses, Particles& p) {
  prepare(poses);
  for (int sweep = 0; sweep < kSeparationSweeps; ++sweep) {
    bool pushed = false;
    for (std::size_t s = 0; s < springs_.size(); ++s)
      for (std::size_t e = 0; e < edges_.size(); ++e) {
        const std::size_t id = s * edges_.size() + e;
        const Spring& sp = springs_[s];
        if (orient3d_sign(p.x[sp.i], p.x[sp.j], end_[e][0], end_[e][1]) != -side_[id]) continue;
        // On the other side: a resting spring that sank through, or one that another contact's
        // placement moved through, is put back; any other went round the edge.
        if (rest_flag_[id] || moved_through(s, e, p.x)) {
          push_out(s, e, poses.end(static_cast<std::size_t>(edges_[e].obstacle)), p);
          ++(rest_flag_[id] ? counters_.resting_corrections : counters_.moved_through);
          pushed = true;
        } else {
          side_[id] = static_cast<std::int8_t>(-side_[id]);
        }
      }
    if (!pushed) return;
  }
}

void EdgeContacts::begin_step(const ObstaclePoses& poses, Particles& p, const std::vector<Vec3>& a_free,
                              const ContactSettings& settings) {
  kept_.clear();
  for (Rest r : resting_) {
    const std::size_t s = r.pair / edges_.size(), e = r.pair % edges_.size();
    const Spring& sp = springs_[s];
    const ObstaclePose& pose = poses.start(static_cast<std::size_t>(edges_[e].obstacle));
    const Obstacle& o = (*obstacles_)[static_cast<std::size_t>(edges_[e].obstacle)];
    const auto ed = edge_at(pose, e);
    const Vec2 st = closest_segment_params(p.x[sp.i], p.x[sp.j], ed[0], ed[1]);
    const bool on_segments = st[0] > 0.0 && st[0] < 1.0 && st[1] > 0.0 && st[1] < 1.0;
    bool keep = on_segments && contact_frame(s, e, pose, p, r.a, r.point, r.normal) &&
                r.normal.dot((1 - r.a) * a_free[sp.i] + r.a * a_free[sp.j]) <= 0.0;
    const double wi = p.inv_mass[sp.i], wj = p.inv_mass[sp.j];
    r.w = (1 - r.a) * (1 - r.a) * wi + r.a * r.a * wj;
    if (keep) {
      // Lifted off the edge (by another contact) farther than its placement gap, or moving away
      // faster than a static contact: released.
      const Vec3 contact = p.x[sp.i] + r.a * (p.x[sp.j] - p.x[sp.i]);
      r.surface_velocity = obstacle_surface_velocity(o, pose, r.point);
      const double vn = r.normal.dot((1 - r.a) * p.v[sp.i] + r.a * p.v[sp.j] - r.surface_velocity);
      keep = r.w > 0.0 && r.normal.dot(contact - r.point) <= kLift * (p.x[sp.j] - p.x[sp.i]).norm() &&
             vn <= settings.static_threshold;
    }
    if (!keep) {
      rest_flag_[r.pair] = 0;
      continue;
    }
    kept_.push_back(r);
  }
  resting_.swap(kept_);
  settle_resting(p);
}

void EdgeContacts::settle_resting(Particles& p) const {
  for (int sweep = 0; sweep < kRestingSweeps; ++sweep)
    for (const Rest& r : resting_) {
      const Spring& sp = springs_[r.pair / edges_.size()];
      const double vn = r.normal.dot((1 - r.a) * p.v[sp.i] + r.a * p.v[sp.j] - r.surface_velocity);
      p.v[sp.i] -= (1 - r.a) * p.inv_mass[sp.i] * vn / r.w * r.normal;
      p.v[sp.j] -= r.a * p.inv_mass[sp.j] * vn / r.w * r.normal;
    }
}

void EdgeContacts::end_step(const ObstaclePoses& poses, Particles& p) { update_sides(poses, p); }

}  // namespace tecido
