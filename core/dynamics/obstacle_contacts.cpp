#include "core/dynamics/obstacle_contacts.h"

#include "core/dynamics/mesh_obstacle_contacts.h"
#include "core/dynamics/obstacle_response.h"
#include "core/geometry/closest_points.h"
#include "core/geometry/segment_box.h"
#include "core/geometry/segment_sphere.h"

#include <algorithm>
#include <cmath>

namespace tecido {

ObstacleContacts::ObstacleContacts(const std::vector<Obstacle>& obstacles, std::size_t n_particles)
    : obstacles_(&obstacles), poses_(obstacles) {
  std::size_t total = 0;
  for (const Obstacle& o : obstacles) {
    offset_.push_back(total);
    stride_.push_back(o.kind == ObstacleKind::Mesh ? o.triangles.size() : 1);
    total += n_particles * stride_.back();
  }
  side_.assign(total, 1);
  rest_flag_.assign(total, 0);
}

void ObstacleContacts::init_sides(const Particles& p, const std::vector<Vec3>& a0) {
  if (obstacles_->empty()) return;
  poses_.at_start(0.0);
  for (std::size_t k = 0; k < obstacles_->size(); ++k) {
    const Obstacle& o = (*obstacles_)[k];
    if (o.kind != ObstacleKind::Mesh) continue;
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t f = 0; f < o.triangles.size(); ++f)
        side_[slot(i, k, static_cast<int>(f))] =
            initial_triangle_side(poses_.start(k), o.triangles[f], p.x[i], p.v[i], a0[i]);
  }
}

std::size_t ObstacleContacts::slot(std::size_t i, std::size_t k, int feature) const {
  const bool mesh = (*obstacles_)[k].kind == ObstacleKind::Mesh;
  return offset_[k] + i * stride_[k] + (mesh ? static_cast<std::size_t>(feature) : 0);
}

ObstacleHit ObstacleContacts::earliest_hit(std::size_t i, const Vec3& x0, const Vec3& x1) {
  ObstacleHit best{static_cast<int>(i), -1, 0, 2.0};
  for (std::size_t k = 0; k < obstacles_->size(); ++k) {
    const Obstacle& o = (*obstacles_)[k];
    const ObstaclePose &a = poses_.start(k), &b = poses_.end(k);
    if (o.kind == ObstacleKind::Mesh) {
      const std::size_t base = slot(i, k, 0);
      const MeshHit m = mesh_earliest_hit(o, a, b, x0, x1, &side_[base], &rest_flag_[base], false);
      if (m.triangle >= 0 && m.s < best.s) best = ObstacleHit{static_cast<int>(i), static_cast<int>(k), m.triangle, m.s};
      continue;
    }
    if (rest_flag_[slot(i, k, 0)]) continue;
    if (o.kind == ObstacleKind::Sphere) {
      const SphereEntry e = segment_enters_sphere(x0 - a.center, x1 - b.center, o.radius);
      if (e.hit && e.s < best.s) best = ObstacleHit{static_cast<int>(i), static_cast<int>(k), 0, e.s};
    } else {
      const BoxEntry e = segment_enters_box(a.to_local(x0), b.to_local(x1), o.half_extents);
      if (e.hit && e.s < best.s) best = ObstacleHit{static_cast<int>(i), static_cast<int>(k), e.face, e.s};
    }
  }
  return best;
}

bool ObstacleContacts::any_hit(double t1, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                               const Particles& p) {
  poses_.at_end(t1);
  for (std::size_t i = 0; i < x0.size(); ++i) {
    if (p.pinned[i]) continue;
    if (earliest_hit(i, x0[i], x1[i]).obstacle >= 0) return true;
  }
  return false;
}

void ObstacleContacts::collect(double t1, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                               const Particles& p, std::vector<ObstacleHit>& hits) {
  hits.clear();
  poses_.at_end(t1);
  for (std::size_t i = 0; i < x0.size(); ++i) {
    if (p.pinned[i]) continue;
    const ObstacleHit h = earliest_hit(i, x0[i], x1[i]);
    if (h.obstacle >= 0) hits.push_back(h);
  }
}

Vec3 ObstacleContacts::surface_velocity(std::size_t k, int feature, const ObstaclePose& pose, const Vec3& x) const {
  const Obstacle& o = (*obstacles_)[k];
  if (o.kind == ObstacleKind::Mesh && !o.frames.empty()) {
    const auto& t = o.triangles[static_cast<std::size_t>(feature)];
    const Vec3 bary = closest_triangle_barycentric(x, pose.vertices[t[0]], pose.vertices[t[1]], pose.vertices[t[2]]);
    return obstacle_surface_velocity(o, pose, x, feature, bary);
  }
  return obstacle_surface_velocity(o, pose, x);
}

std::optional<ContactKind> ObstacleContacts::resolve(const ObstacleHit& h, double t1, const std::vector<Vec3>& x0,
                                                     Particles& p, const ContactSettings& settings) {
  const std::size_t i = static_cast<std::size_t>(h.particle), k = static_cast<std::size_t>(h.obstacle);
  const Obstacle& o = (*obstacles_)[k];
  poses_.at_end(t1);
  const ObstaclePose &a = poses_.start(k), &b = poses_.end(k);
  const Vec3 path = p.x[i] - x0[i];
  Vec3 n;
  if (o.kind == ObstacleKind::Sphere) {
    // Where the relative path reaches the sphere, on the sphere at t1.
    const Vec3 r = (x0[i] - a.center) + h.s * ((p.x[i] - b.center) - (x0[i] - a.center));
    Vec3 x = b.center + r;
    place_on_feature(i, k, 0, b, x, n);  // on the sphere, and outside it after rounding
    p.x[i] = x;
  } else if (o.kind == ObstacleKind::Box) {
    const Vec3 q0 = a.to_local(x0[i]), q1 = b.to_local(p.x[i]);
    Vec3 x = b.to_world(project_on_box_face(q0 + h.s * (q1 - q0), o.half_extents, h.feature));
    place_on_feature(i, k, h.feature, b, x, n);
    p.x[i] = x;
  } else {
    const auto& t = o.triangles[static_cast<std::size_t>(h.feature)];
    const Vec3 xc = x0[i] + h.s * path;
    Vec3 tri[3];
    for (int c = 0; c < 3; ++c) tri[c] = a.vertices[t[c]] + h.s * (b.vertices[t[c]] - a.vertices[t[c]]);
    const Vec3 bary = closest_triangle_barycentric(xc, tri[0], tri[1], tri[2]);
    const int side = side_[slot(i, k, h.feature)];
    p.x[i] = place_on_triangle(b, t, bary, side);
    n = triangle_normal_towards(b, t, side);
  }
  const Vec3 u = surface_velocity(k, h.feature, b, p.x[i]);
  const double kel = o.elasticity ? *o.elasticity : p.elasticity[i];
  const std::optional<ContactKind> kind = respond_to_moving_contact(p.v[i], u, n, kel, o.friction, settings);
  if (!kind) {
    ++counters_.separating;
    return kind;
  }
  ++counters_.contacts;
  if (*kind == ContactKind::Static) {
    const std::size_t id = slot(i, k, h.feature);
    if (!rest_flag_[id]) {
      rest_flag_[id] = 1;
      resting_.push_back(ObstacleRest{h.particle, h.obstacle, h.feature, n});
    }
  }
  return kind;
}

void ObstacleContacts::update_sides(double t1, const std::vector<Vec3>& x) {
  poses_.at_end(t1);
  for (std::size_t k = 0; k < obstacles_->size(); ++k) {
    const Obstacle& o = (*obstacles_)[k];
    if (o.kind != ObstacleKind::Mesh) continue;
    const ObstaclePose& b = poses_.end(k);
    for (std::size_t i = 0; i < x.size(); ++i)
      for (std::size_t f = 0; f < o.triangles.size(); ++f) {
        const std::size_t id = slot(i, k, static_cast<int>(f));
        if (rest_flag_[id]) continue;
        if (triangle_side(b, o.triangles[f], x[i]) == -side_[id]) side_[id] = static_cast<std::int8_t>(-side_[id]);
      }
  }
}

void ObstacleContacts::place_on_feature(std::size_t i, std::size_t k, int feature, const ObstaclePose& pose, Vec3& x,
                                        Vec3& normal) const {
  const Obstacle& o = (*obstacles_)[k];
  if (o.kind == ObstacleKind::Sphere) {
    const Vec3 on = place_on_sphere(x - pose.center, o.radius);
    normal = on.normalized();
    x = pose.center + on;
    // Adding the centre rounds: the world point may be inside again. Move it out by ulps.
    double step = 0x1p-52 * std::max({x.cwiseAbs().maxCoeff(), o.radius, 1e-300});
    for (int tries = 0; tries < 64 && inside_sphere(x - pose.center, o.radius); ++tries) {
      x += step * normal;
      step *= 2.0;
    }
    return;
  }
  if (o.kind == ObstacleKind::Box) {
    const Vec3& h = o.half_extents;
    normal = pose.rotation * box_face_normal(feature);
    x = pose.to_world(project_on_box_face(pose.to_local(x), h, feature));
    // Rounding in the rotation can leave the point inside: move it out along the normal by ulps.
    double step = 0x1p-52 * std::max({x.cwiseAbs().maxCoeff(), h.maxCoeff(), 1e-300});
    for (int tries = 0; tries < 64 && inside_box(pose.to_local(x), h); ++tries) {
      x += step * normal;
      step *= 2.0;
    }
    return;
  }
  const auto& t = o.triangles[static_cast<std::size_t>(feature)];
  const int side = side_[slot(i, k, feature)];
  const Vec3 bary = triangle_projection_barycentric(pose, t, x);
  const Vec3 w = bary.cwiseMax(0.0) / std::max(bary.cwiseMax(0.0).sum(), 1e-300);
  x = place_on_triangle(pose, t, w, side);
  normal = triangle_normal_towards(pose, t, side);
}

bool ObstacleContacts::keep_resting(const ObstacleRest& r, const ObstaclePose& pose, const Particles& p,
                                    const Vec3& a) const {
  const std::size_t i = static_cast<std::size_t>(r.particle), k = static_cast<std::size_t>(r.obstacle);
  const Obstacle& o = (*obstacles_)[k];
  const Vec3& x = p.x[i];
  // Lifted off (by another contact, e.g. a spring held over an edge): no longer resting. The
  // tolerance is far above the rounding of a placement, far below any motion.
  const double lift_tol = kLiftTolerance * std::max(x.cwiseAbs().maxCoeff(), pose.center.cwiseAbs().maxCoeff());
  if (o.kind == ObstacleKind::Sphere) {
    const Vec3 rel = x - pose.center;
    const double len = rel.norm();
    // No lift-off test: sliding along the tangent ends above the curve by about (v dt)^2 / 2r
    // every step; the particle is put back on the sphere below, or released by the pull test.
    if (!(len > 0.0)) return false;
    const Vec3 n = rel / len;
    const Vec3 vrel = p.v[i] - obstacle_surface_velocity(o, pose, x);
    const Vec3 vt = vrel - n * n.dot(vrel);
    // Held on the curve only while the pull towards the centre exceeds what the curve needs.
    return a.dot(n) + vt.squaredNorm() / o.radius <= 0.0;
  }
  if (o.kind == ObstacleKind::Box) {
    const Vec3 n = pose.rotation * box_face_normal(r.feature);
    if (a.dot(n) > 0.0) return false;
    const Vec3 q = pose.to_local(x);
    const int axis = r.feature / 2;
    const double out = ((r.feature & 1) ? q[axis] : -q[axis]) - o.half_extents[axis];
    if (out > lift_tol + kLiftTolerance * o.half_extents.maxCoeff()) return false;
    for (int ax = 0; ax < 3; ++ax)
      if (ax != axis && !(std::abs(q[ax]) <= o.half_extents[ax])) return false;
    return true;
  }
  const auto& t = o.triangles[static_cast<std::size_t>(r.feature)];
  const Vec3 n = triangle_normal_towards(pose, t, side_[slot(i, k, r.feature)]);
  if (a.dot(n) > 0.0) return false;
  if (n.dot(x - pose.vertices[t[0]]) > lift_tol + kLiftTolerance * pose.vertices[t[0]].cwiseAbs().maxCoeff()) return false;
  const Vec3 w = triangle_projection_barycentric(pose, t, x);
  return w.minCoeff() >= 0.0;
}

void ObstacleContacts::begin_step(double t, Particles& p, const std::vector<Vec3>& a_free,
                                  const ContactSettings& settings) {
  if (resting_.empty()) return;
  poses_.at_start(t);
  kept_.clear();
  for (ObstacleRest r : resting_) {
    const std::size_t i = static_cast<std::size_t>(r.particle), k = static_cast<std::size_t>(r.obstacle);
    const ObstaclePose& pose = poses_.start(k);
    const std::size_t id = slot(i, k, r.feature);
    if (!keep_resting(r, pose, p, a_free[i])) {
      rest_flag_[id] = 0;
      continue;
    }
    place_on_feature(i, k, r.feature, pose, p.x[i], r.normal);
    const Obstacle& o = (*obstacles_)[k];
    const Vec3 u = surface_velocity(k, r.feature, pose, p.x[i]);
    Vec3 rel = p.v[i] - u;
    respond_to_contact(rel, r.normal, o.elasticity ? *o.elasticity : p.elasticity[i], o.friction, settings);
    p.v[i] = rel + u;
    kept_.push_back(r);
  }
  resting_.swap(kept_);
}

void ObstacleContacts::cancel_resting(std::vector<Vec3>& a) const {
  for (const ObstacleRest& r : resting_) {
    const double an = r.normal.dot(a[static_cast<std::size_t>(r.particle)]);
    if (an < 0.0) a[static_cast<std::size_t>(r.particle)] -= an * r.normal;
  }
}

void ObstacleContacts::end_step(double t, Particles& p) {
  poses_.at_end(t);
  for (ObstacleRest& r : resting_) {
    const std::size_t i = static_cast<std::size_t>(r.particle), k = static_cast<std::size_t>(r.obstacle);
    const Obstacle& o = (*obstacles_)[k];
    const ObstaclePose& pose = poses_.end(k);
    bool inside;
    if (o.kind == ObstacleKind::Sphere) {
      inside = inside_sphere(p.x[i] - pose.center, o.radius);
    } else if (o.kind == ObstacleKind::Box) {
      inside = inside_box(pose.to_local(p.x[i]), o.half_extents);
    } else {
      const int side = side_[slot(i, k, r.feature)];
      inside = triangle_side(pose, o.triangles[static_cast<std::size_t>(r.feature)], p.x[i]) == -side;
    }
    if (!inside) continue;
    Vec3 n;
    place_on_feature(i, k, r.feature, pose, p.x[i], n);
    ++counters_.resting_corrections;
  }
  for (std::size_t k = 0; k < obstacles_->size(); ++k) {
    const Obstacle& o = (*obstacles_)[k];
    if (o.kind == ObstacleKind::Mesh) continue;
    const ObstaclePose& pose = poses_.end(k);
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.pinned[i]) continue;
      const Vec3 q = pose.to_local(p.x[i]);
      const bool inside =
          o.kind == ObstacleKind::Sphere ? inside_sphere(p.x[i] - pose.center, o.radius) : inside_box(q, o.half_extents);
      if (!inside) continue;
      const int feature = o.kind == ObstacleKind::Box ? nearest_box_face(q, o.half_extents) : 0;
      Vec3 n;
      place_on_feature(i, k, feature, pose, p.x[i], n);
      const Vec3 u = surface_velocity(k, feature, pose, p.x[i]);
      const double vn = n.dot(p.v[i] - u);
      if (vn < 0.0) p.v[i] -= vn * n;
      ++counters_.guard_corrections;
    }
  }
}

}  // namespace tecido
