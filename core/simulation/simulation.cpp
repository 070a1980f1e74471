#include "core/simulation/simulation.h"

#include "core/geometry/plane_side.h"
#include "core/geometry/segment_plane.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace tecido {

namespace {
std::int8_t sign_of(double s) { return s > 0.0 ? 1 : (s < 0.0 ? -1 : 0); }
}  // namespace

Simulation::Simulation(const Scene& scene)
    : scene_(scene),
      p_(scene.particles),
      springs_(scene.forces.springs),
      integ_(scene.integrator),
      obstacles_(scene_.obstacles, scene.particles.size()),
      edges_(scene_.obstacles, scene_.forces.springs, scene_.particles.pinned, scene_.edge_contacts),
      spring_boxes_(scene_.obstacles, scene_.forces.springs, scene_.particles.pinned, scene_.edge_contacts) {
  tol_ = scene_.contact.bisection_tolerance > 0.0 ? scene_.contact.bisection_tolerance : scene_.dt * 0x1.0p-20;
  accel_ = [this](double t, const std::vector<Vec3>& x, const std::vector<Vec3>& v, std::vector<Vec3>& a) {
    accelerations(t, x, v, a);
  };
  n_planes_ = scene_.planes.size();
  const std::size_t n = p_.size();
  side_.assign(n * n_planes_, 1);
  resting_flag_.assign(n * n_planes_, 0);
  if (n_planes_ == 0 && obstacles_.empty()) return;
  // Initial sides: the side the particle is on (exact sign, the one segment_plane decides
  // crossings with); on the plane, the side it comes from (against its velocity, else against its
  // free acceleration, else the normal's side). Mesh obstacles' triangles likewise.
  compute_accelerations(scene_.forces, springs_, p_.inv_mass, 0.0, p_.x, p_.v, a_free_);
  obstacles_.init_sides(p_, a_free_);
  if (!edges_.empty()) {
    obstacles_.poses().at_start(0.0);
    edges_.init_sides(obstacles_.poses(), p_);
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < n_planes_; ++k) {
      const BoundedPlane& pl = scene_.planes[k];
      std::int8_t s = static_cast<std::int8_t>(plane_side_sign(pl, p_.x[i]));
      if (s == 0) s = static_cast<std::int8_t>(-sign_of(pl.normal.dot(p_.v[i])));
      if (s == 0) s = static_cast<std::int8_t>(-sign_of(pl.normal.dot(a_free_[i])));
      if (s == 0) s = 1;
      side_[i * n_planes_ + k] = s;
    }
  }
}

void Simulation::accelerations(double t, const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                               std::vector<Vec3>& a) {
  compute_accelerations(scene_.forces, springs_, p_.inv_mass, t, x, v, a);
  // Resting contacts: the plane cancels the part of the acceleration that points into it.
  for (const auto& [i, k] : resting_) {
    const Vec3& n = scene_.planes[k].normal;
    const double an = n.dot(a[i]);
    if (side_[i * n_planes_ + k] * an < 0.0) a[i] -= an * n;
  }
  obstacles_.cancel_resting(a);
}

bool Simulation::any_contact(double t1, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  if (any_hit(x0, x1)) return true;
  if (obstacles_.empty()) return false;
  if (obstacles_.any_hit(t1, x0, x1, p_)) return true;  // sets the poses at t1
  if (!spring_boxes_.empty() && spring_boxes_.any_hit(obstacles_.poses(), x0, x1)) return true;
  return !edges_.empty() && edges_.any_hit(obstacles_.poses(), x0, x1);
}

bool Simulation::any_hit(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  const std::size_t n = p_.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (p_.pinned[i]) continue;
    for (std::size_t k = 0; k < n_planes_; ++k) {
      const std::size_t id = i * n_planes_ + k;
      if (resting_flag_[id]) continue;
      const BoundedPlane& pl = scene_.planes[k];
      // Still strictly on its side (exactly: a rounded side could skip an end point exactly on
      // the plane, or just past it, that segment_plane counts as a hit).
      if (plane_side_sign(pl, x1[i]) == side_[id]) continue;
      if (segment_plane(pl, x0[i], x1[i]).hit) return true;
    }
  }
  return false;
}

void Simulation::collect_hits(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, std::vector<Hit>& hits) {
  hits.clear();
  const std::size_t n = p_.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (p_.pinned[i]) continue;
    Hit best{static_cast<int>(i), -1, 2.0};
    for (std::size_t k = 0; k < n_planes_; ++k) {
      const std::size_t id = i * n_planes_ + k;
      if (resting_flag_[id]) continue;
      const BoundedPlane& pl = scene_.planes[k];
      if (plane_side_sign(pl, x1[i]) == side_[id]) continue;
      const SegmentPlaneHit h = segment_plane(pl, x0[i], x1[i]);
      if (h.hit && h.t < best.t) best = Hit{static_cast<int>(i), static_cast<int>(k), h.t};
    }
    if (best.plane >= 0) hits.push_back(best);
  }
}

void Simulation::update_sides(const std::vector<Vec3>& x) {
  // A particle that ended strictly on the other side without a hit went around the rectangle.
  const std::size_t n = p_.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < n_planes_; ++k) {
      const std::size_t id = i * n_planes_ + k;
      if (resting_flag_[id]) continue;
      if (plane_side_sign(scene_.planes[k], x[i]) == -side_[id]) side_[id] = static_cast<std::int8_t>(-side_[id]);
    }
  }
}

void Simulation::place_on_plane(int i, int k) {
  // Project onto the plane, then make sure rounding leaves the particle on its own side or on
  // the plane, exactly (the side the contact tests use). The rounded side can be 0 or of the
  // right sign while the exact one is not, so each nudge is also at least about one ulp of the
  // largest coordinate, doubling per try.
  const BoundedPlane& pl = scene_.planes[k];
  const int s = side_[i * n_planes_ + k];
  Vec3& x = p_.x[i];
  x -= pl.normal * pl.side(x);
  double floor = 0x1p-52 * x.cwiseAbs().maxCoeff();
  for (int tries = 0; tries < 8 && plane_side_sign(pl, x) == -s; ++tries) {
    x += pl.normal * (s * std::max({std::abs(pl.side(x)) * 2.0, floor, 1e-300}));
    floor *= 2.0;
  }
}

void Simulation::resolve_hit(const Hit& h, const std::vector<Vec3>& x0, double t_contact) {
  const int i = h.particle, k = h.plane;
  const BoundedPlane& pl = scene_.planes[k];
  p_.x[i] = x0[i] + h.t * (p_.x[i] - x0[i]);
  place_on_plane(i, k);
  const Vec3 before = p_.v[i];
  const ContactKind kind = respond_to_contact(p_.v[i], pl.normal, p_.elasticity[i], pl.friction, scene_.contact);
  if (log_contacts_) contact_log_.push_back(ContactEvent{step_, t_contact, i, k, kind, before, p_.v[i]});
  if (kind == ContactKind::Elastic) {
    ++counters_.elastic;
  } else {
    ++counters_.static_contacts;
    const std::size_t id = static_cast<std::size_t>(i) * n_planes_ + k;
    if (!resting_flag_[id]) {
      resting_flag_[id] = 1;
      resting_.emplace_back(i, k);
    }
  }
}

void Simulation::update_obstacle_sides(double t1) {
  if (obstacles_.empty()) return;
  obstacles_.update_sides(t1, p_.x);  // sets the poses at t1
  if (!spring_boxes_.empty()) spring_boxes_.move_out_all(obstacles_.poses(), p_);
  if (!edges_.empty()) edges_.update_sides(obstacles_.poses(), p_);
}

void Simulation::resolve_obstacle_hit(const ObstacleHit& h, const std::vector<Vec3>& x0, double t_contact) {
  const int i = h.particle;
  const Vec3 before = p_.v[i];
  const std::optional<ContactKind> kind = obstacles_.resolve(h, t_contact, x0, p_, scene_.contact);
  if (!kind) return;
  if (log_contacts_)
    contact_log_.push_back(ContactEvent{step_, t_contact, i, -1, *kind, before, p_.v[i], h.obstacle, h.feature});
  if (*kind == ContactKind::Elastic) {
    ++counters_.elastic;
  } else {
    ++counters_.static_contacts;
  }
}

void Simulation::resolve_contacts(double t1, const std::vector<Vec3>& x0) {
  collect_hits(x0, p_.x, hits_);
  if (obstacles_.empty()) {
    for (const Hit& hit : hits_) resolve_hit(hit, x0, t1);
    return;
  }
  obstacles_.collect(t1, x0, p_.x, p_, obstacle_hits_);
  // Spring-edge contacts over the same motion, resolved after the particles' own.
  if (!edges_.empty()) edges_.collect(obstacles_.poses(), x0, p_.x, edge_hits_);
  if (!spring_boxes_.empty()) spring_boxes_.collect(obstacles_.poses(), x0, p_.x, spring_box_hits_);
  // Both lists are in particle order with at most one entry per particle: each particle's
  // earlier contact is resolved (a plane on a tie).
  std::size_t a = 0, b = 0;
  while (a < hits_.size() || b < obstacle_hits_.size()) {
    const int pa = a < hits_.size() ? hits_[a].particle : std::numeric_limits<int>::max();
    const int pb = b < obstacle_hits_.size() ? obstacle_hits_[b].particle : std::numeric_limits<int>::max();
    if (pa < pb) {
      resolve_hit(hits_[a++], x0, t1);
    } else if (pb < pa) {
      resolve_obstacle_hit(obstacle_hits_[b++], x0, t1);
    } else if (hits_[a].t <= obstacle_hits_[b].s) {
      resolve_hit(hits_[a++], x0, t1);
      ++b;
    } else {
      resolve_obstacle_hit(obstacle_hits_[b++], x0, t1);
      ++a;
    }
  }
  if (!spring_boxes_.empty()) spring_boxes_.resolve(spring_box_hits_, obstacles_.poses(), p_, scene_.contact);
  if (edges_.empty()) return;
  for (const EdgeHit& h : edge_hits_) edges_.resolve(h, obstacles_.poses(), p_, scene_.contact);
  edges_.separate(edge_hits_, obstacles_.poses(), p_);
}

void Simulation::begin_step_resting(double t) {
  if (resting_.empty() && obstacles_.resting().empty() && edges_.resting_count() == 0 &&
      spring_boxes_.resting_count() == 0)
    return;
  // Release contacts whose free acceleration pulls away or that slid off the rectangle; keep the
  // others on the plane with no normal velocity, and apply friction once per step.
  compute_accelerations(scene_.forces, springs_, p_.inv_mass, t, p_.x, p_.v, a_free_);
  std::vector<std::pair<int, int>>& kept = resting_scratch_;  // reused: no allocation per step
  kept.clear();
  for (const auto& [i, k] : resting_) {
    const BoundedPlane& pl = scene_.planes[k];
    const std::size_t id = static_cast<std::size_t>(i) * n_planes_ + k;
    const double s = side_[id];
    if (s * pl.normal.dot(a_free_[i]) > 0.0 || !pl.contains_projection(p_.x[i])) {
      resting_flag_[id] = 0;
      continue;
    }
    place_on_plane(i, k);
    respond_to_contact(p_.v[i], pl.normal, p_.elasticity[i], pl.friction, scene_.contact);
    kept.emplace_back(i, k);
  }
  resting_.swap(kept);
  obstacles_.begin_step(t, p_, a_free_, scene_.contact);
  if (edges_.resting_count() > 0 || spring_boxes_.resting_count() > 0) {
    obstacles_.poses().at_start(t);
    edges_.begin_step(obstacles_.poses(), p_, a_free_, scene_.contact);
    spring_boxes_.begin_step(obstacles_.poses(), p_, scene_.contact);
  }
}

bool Simulation::check_finite() {
  const std::size_t n = p_.size();
  // Fast path: a double is NaN or infinite exactly when its 11 exponent bits are all ones,
  // i.e. when adding 1 to the exponent field carries into the sign bit. OR-ing that sum over
  // the flat arrays is a branch-free integer loop the compiler vectorizes; only when it finds
  // something does the per-particle scan below name the particle and the quantity.
  auto any_non_finite = [](const std::vector<Vec3>& a) {
    const std::size_t m = 3 * a.size();
    const double* d = a.empty() ? nullptr : a.front().data();
    constexpr std::uint64_t kExp = 0x7ff0000000000000ull, kExpOne = 1ull << 52, kSign = 1ull << 63;
    std::uint64_t acc = 0;
    for (std::size_t k = 0; k < m; ++k) {
      std::uint64_t b;
      std::memcpy(&b, d + k, sizeof b);
      acc |= (b & kExp) + kExpOne;
    }
    return (acc & kSign) != 0;
  };
  if (!any_non_finite(p_.x) && !any_non_finite(p_.v)) return true;
  for (std::size_t i = 0; i < n; ++i) {
    const char* what = !p_.x[i].allFinite() ? "position" : (!p_.v[i].allFinite() ? "velocity" : nullptr);
    if (what) {
      instability_ = Instability{step_, static_cast<int>(i), what};
      return false;
    }
  }
  return true;
}

bool Simulation::step() {
  if (instability_) return false;
  const double h = scene_.dt;
  double t = time();
  ++step_;
  begin_step_resting(t);
  if (n_planes_ == 0 && obstacles_.empty()) {
    integ_.step(accel_, t, h, p_.x, p_.v);
  } else {
    double remaining = h;
    int events = 0;
    while (remaining > 0.0) {
      x0_ = p_.x;
      v0_ = p_.v;
      obstacles_.poses().at_start(t);
      integ_.step(accel_, t, remaining, p_.x, p_.v);
      if (!any_contact(t + remaining, x0_, p_.x)) {
        update_sides(p_.x);
        update_obstacle_sides(t + remaining);
        break;
      }
      double hi = remaining;
      if (events >= scene_.contact.max_events_per_step) {
        // Cap reached: resolve the remaining contacts where their paths reach the surfaces, unbisected.
        ++counters_.cap_hits;
      } else {
        // Bisection on the step (fig. 8): lo never crosses, hi does.
        double lo = 0.0;
        while (hi - lo > tol_) {
          const double mid = 0.5 * (lo + hi);
          if (!(mid > lo && mid < hi)) break;
          xm_ = x0_;
          vm_ = v0_;
          integ_.step(accel_, t, mid, xm_, vm_);
          ++counters_.bisections;
          if (any_contact(t + mid, x0_, xm_)) {
            hi = mid;
          } else {
            lo = mid;
          }
        }
        if (hi < remaining) {
          p_.x = x0_;
          p_.v = v0_;
          integ_.step(accel_, t, hi, p_.x, p_.v);
        }
        ++counters_.events;
      }
      resolve_contacts(t + hi, x0_);
      update_sides(p_.x);
      update_obstacle_sides(t + hi);
      ++events;
      t += hi;
      remaining = (hi >= remaining) ? 0.0 : remaining - hi;
      if (!check_finite()) return false;
    }
  }
  if (post_step) post_step(*this);
  if (!obstacles_.empty()) {
    obstacles_.poses().at_end(time());
    if (!edges_.empty()) edges_.end_step(obstacles_.poses(), p_);
    if (!spring_boxes_.empty()) spring_boxes_.move_out_all(obstacles_.poses(), p_);
    obstacles_.end_step(time(), p_);
  }
  return check_finite();
}

bool Simulation::run(long long n, const std::function<void(const Simulation&)>& on_frame) {
  for (long long s = 0; s < n; ++s) {
    if (!step()) return false;
    if (on_frame) on_frame(*this);
  }
  return true;
}

}  // namespace tecido
