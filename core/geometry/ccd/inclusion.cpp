#include "core/geometry/ccd/inclusion.h"

#include "core/geometry/ccd/closest_params.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace tecido {

namespace {

/// A parameter box; index 0 = t, 1 = u, 2 = v, each [lo, hi]. A slab spans the whole (u, v)
/// domain over its time interval.
struct Box {
  double lo[3], hi[3];
  bool slab;
};

constexpr double kMinWidth = 0x1p-40;

/// X(t) = X0 + t dX per coordinate (and Y, Z), with the per-coordinate error bounds.
struct Motion {
  double x0[3], dx[3], y0[3], dy[3], z0[3], dz[3];
  double err[3];
};

Motion motion_of(const CcdSystem& s) {
  Motion m;
  for (int c = 0; c < 3; ++c) {
    m.x0[c] = s.d[0][CcdSystem::X][c];
    m.dx[c] = s.d[1][CcdSystem::X][c] - m.x0[c];
    m.y0[c] = s.d[0][CcdSystem::Y][c];
    m.dy[c] = s.d[1][CcdSystem::Y][c] - m.y0[c];
    m.z0[c] = s.d[0][CcdSystem::Z][c];
    m.dz[c] = s.d[1][CcdSystem::Z][c] - m.z0[c];
    m.err[c] = 0x1p-47 * s.mag[c] + 0x1p-900;
  }
  return m;
}

/// F(t, u, v) per coordinate, by the same operations as corner_values (so with the same
/// error bound, m.err, for any t, u, v in [0, 1]); dF/dt at (u, v) (approximate) in ft.
void value_at(const Motion& m, double t, double u, double v, double f[3], double ft[3]) {
  for (int c = 0; c < 3; ++c) {
    const double x = m.x0[c] + t * m.dx[c], y = m.y0[c] + t * m.dy[c], z = m.z0[c] + t * m.dz[c];
    f[c] = (z - u * x) - v * y;
    ft[c] = m.dz[c] - u * m.dx[c] - v * m.dy[c];
  }
}

/// F at the 8 corners of b: f[corner][c], corner = 4 * (t is hi) + 2 * (u is hi) + (v is hi).
/// For a vertex-face slab, corner (1, 1) lies outside the triangle: it repeats (1, 0), so the
/// values span the image of the prism [t0, t1] x triangle (F is affine on the triangle).
void corner_values(const Motion& m, const Box& b, bool vf, double f[8][3]) {
  for (int ti = 0; ti < 2; ++ti) {
    const double t = ti ? b.hi[0] : b.lo[0];
    for (int c = 0; c < 3; ++c) {
      const double x = m.x0[c] + t * m.dx[c], y = m.y0[c] + t * m.dy[c], z = m.z0[c] + t * m.dz[c];
      for (int ui = 0; ui < 2; ++ui) {
        const double g = z - (ui ? b.hi[1] : b.lo[1]) * x;
        f[4 * ti + 2 * ui][c] = g - b.lo[2] * y;
        f[4 * ti + 2 * ui + 1][c] = g - b.hi[2] * y;
      }
    }
  }
  if (vf && b.slab)
    for (int ti = 0; ti < 2; ++ti)
      for (int c = 0; c < 3; ++c) f[4 * ti + 3][c] = f[4 * ti + 2][c];
}

/// True when every corner value lies strictly on one side of the plane through 0 normal to d
/// (any direction: the test is sound for all). d . F_k is within
/// sum_c |d_c| (err_c + 4 eps |F_kc|) of d . (true F_k) (the corner errors, then three
/// roundings of the dot product); the generous constant absorbs the bound's own rounding.
bool excluded_along(const double d[3], const double f[8][3], const double err[3], const double big[3]) {
  double bound = 0.0;
  for (int c = 0; c < 3; ++c) bound += std::fabs(d[c]) * (err[c] + 0x1p-50 * big[c]);
  bound *= 1.0 + 0x1p-40;
  double smin = 0.0, smax = 0.0;
  for (int k = 0; k < 8; ++k) {
    const double sk = d[0] * f[k][0] + d[1] * f[k][1] + d[2] * f[k][2];
    smin = k == 0 ? sk : std::min(smin, sk);
    smax = k == 0 ? sk : std::max(smax, sk);
  }
  return smin > bound || smax < -bound;
}

/// A direction along which F(t_m, u, v) does not depend on (u, v) at the box's mid time t_m:
/// the normal X x Y, or, when X and Y are (nearly) parallel or zero, the part of Z
/// orthogonal to the longer of them (or Z itself). Near a contact the corner values then
/// spread only with the box's time width, which is what separates a thin box from a contact
/// set that is a curve (zero-area triangles, parallel or zero-length edges).
void flat_direction(const Motion& m, double t, double d[3]) {
  double x[3], y[3], z[3];
  for (int c = 0; c < 3; ++c) {
    x[c] = m.x0[c] + t * m.dx[c];
    y[c] = m.y0[c] + t * m.dy[c];
    z[c] = m.z0[c] + t * m.dz[c];
  }
  const double n[3] = {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
  const double xx = x[0] * x[0] + x[1] * x[1] + x[2] * x[2], yy = y[0] * y[0] + y[1] * y[1] + y[2] * y[2];
  const double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  if (nn > 0x1p-40 * xx * yy) {
    for (int c = 0; c < 3; ++c) d[c] = n[c];
    return;
  }
  const double* e = xx >= yy ? x : y;
  const double ee = std::max(xx, yy);
  const double k = ee > 0 ? (z[0] * e[0] + z[1] * e[1] + z[2] * e[2]) / ee : 0.0;
  for (int c = 0; c < 3; ++c) d[c] = z[c] - k * e[c];
}

/// True when the corner values certify that F has no zero in the box: all beyond +-err in
/// one coordinate, or all strictly on one side of a plane through 0, normal to the sum of the
/// corner values or to flat_direction. Fills the per-coordinate range [lo, hi].
bool excluded(const Motion& m, const Box& b, const double f[8][3], double lo[3], double hi[3]) {
  double d[3] = {0.0, 0.0, 0.0}, big[3];
  for (int c = 0; c < 3; ++c) {
    lo[c] = hi[c] = f[0][c];
    for (int k = 1; k < 8; ++k) {
      lo[c] = std::min(lo[c], f[k][c]);
      hi[c] = std::max(hi[c], f[k][c]);
    }
    if (lo[c] > m.err[c] || hi[c] < -m.err[c]) return true;
    for (int k = 0; k < 8; ++k) d[c] += f[k][c];
    big[c] = std::max(std::fabs(lo[c]), std::fabs(hi[c]));
  }
  if (excluded_along(d, f, m.err, big)) return true;
  flat_direction(m, 0.5 * (b.lo[0] + b.hi[0]), d);
  return excluded_along(d, f, m.err, big);
}

/// The parameter (0 t, 1 u, 2 v) along which F changes most across the box, among those
/// still wider than kMinWidth; -1 when none is.
int split_axis(const Box& b, const double f[8][3]) {
  double change[3] = {0.0, 0.0, 0.0};
  for (int k = 0; k < 8; ++k) {
    for (int a = 0; a < 3; ++a) {
      const int bit = 4 >> a;  // t: 4, u: 2, v: 1
      if (k & bit) continue;
      for (int c = 0; c < 3; ++c) change[a] = std::max(change[a], std::fabs(f[k | bit][c] - f[k][c]));
    }
  }
  int best = -1;
  for (int a = 0; a < 3; ++a) {
    if (b.hi[a] - b.lo[a] <= kMinWidth) continue;
    if (best < 0 || change[a] > change[best]) best = a;
  }
  return best;
}

}  // namespace

namespace {

/// Slabs examined per call before the remaining ones are searched as general boxes.
constexpr int kMaxSlabs = 96;

class InclusionSearch {
 public:
  InclusionSearch(const CcdSystem& s, double delta, double tau, int max_boxes)
      : m_(motion_of(s)), vf_(s.kind == CcdKind::VertexFace), delta_(delta), tau_(tau), max_boxes_(max_boxes) {}

  CcdInclusionResult run(double t_lo, double t_hi) {
    thread_local std::vector<Box> stack;
    stack_ = &stack;
    stack.clear();
    stack.push_back({{t_lo, 0.0, 0.0}, {t_hi, 1.0, 1.0}, true});
    while (!stack.empty()) {
      Box b = stack.back();
      stack.pop_back();
      if (r_.hit) {
        // Only times before the best accepted box can improve toi: clip the box there.
        if (b.lo[0] >= best_) continue;
        b.hi[0] = std::min(b.hi[0], best_);
      }
      if (r_.boxes >= max_boxes_) {
        capped(b);
        break;
      }
      ++r_.boxes;
      if (b.slab && slabs_ < kMaxSlabs) {
        ++slabs_;
        slab(b);
      } else {
        b.slab = false;
        general(b);
      }
    }
    return r_;
  }

 private:
  /// The cap: hit at the earliest time any remaining box could hold a contact.
  void capped(const Box& b) {
    double first = b.lo[0];
    for (const Box& o : *stack_) first = std::min(first, o.lo[0]);
    r_.toi = r_.hit ? std::min(best_, first) : first;
    r_.hit = r_.capped = true;
  }

  void accept(double t) {
    best_ = r_.toi = std::min(best_, t);
    r_.hit = true;
  }

  /// The closest parameters at time t (approximate) and F there.
  void closest(double t, double& u, double& v, double f[3], double ft[3]) const {
    double x[3], y[3], z[3];
    for (int c = 0; c < 3; ++c) {
      x[c] = m_.x0[c] + t * m_.dx[c];
      y[c] = m_.y0[c] + t * m_.dy[c];
      z[c] = m_.z0[c] + t * m_.dz[c];
    }
    if (vf_) {
      ccd_closest_on_triangle(x, y, z, u, v);
    } else {
      ccd_closest_on_segments(x, y, z, u, v);
    }
    value_at(m_, t, u, v, f, ft);
  }

  /// True when the computed F (rigorous error m_.err per coordinate) certifies |F| <= delta.
  bool within_delta(const double f[3]) const {
    double sum = 0.0;
    for (int c = 0; c < 3; ++c) sum += (std::fabs(f[c]) + m_.err[c]) * (std::fabs(f[c]) + m_.err[c]);
    return sum * (1.0 + 0x1p-40) <= delta_ * delta_;
  }

  /// A whole-domain slab [t0, t1]: exclusion (the general tests, then the direction of the
  /// closest points at mid-slab: at a fixed time the image of the domain is convex, so that
  /// direction separates it from 0 whenever they are apart, and over the slab as long as the
  /// motion is smaller than the distance), acceptance at t0 (or t1 for a slab within the time
  /// tolerance) by a certified small distance, then a jump to the time of closest approach,
  /// else bisection in time.
  void slab(const Box& b) {
    double f[8][3], lo[3], hi[3], big[3];
    corner_values(m_, b, vf_, f);
    if (excluded(m_, b, f, lo, hi)) return;
    for (int c = 0; c < 3; ++c) big[c] = std::max(std::fabs(lo[c]), std::fabs(hi[c]));
    const double t0 = b.lo[0], t1 = b.hi[0], w = t1 - t0;
    double u, v, r[3], rt[3];
    closest(0.5 * (t0 + t1), u, v, r, rt);
    if (excluded_along(r, f, m_.err, big)) return;
    closest(t0, u, v, r, rt);
    if (within_delta(r)) return accept(t0);
    if (w <= tau_) {
      closest(t1, u, v, r, rt);
      if (within_delta(r)) return accept(t0);
    }
    if (w > 0x1p-44 && jump(b)) return;
    if (w <= 0x1p-44) {
      Box g = b;
      g.slab = false;
      stack_->push_back(g);
      return;
    }
    const double mid = 0.5 * (t0 + t1);
    stack_->push_back({{mid, 0.0, 0.0}, {t1, 1.0, 1.0}, true});
    stack_->push_back({{t0, 0.0, 0.0}, {mid, 1.0, 1.0}, true});
  }

  /// Newton-like iteration on the time of closest approach of the linearised relative motion
  /// (t <- t - R . V / V . V, R = F at the closest parameters, V = dF/dt there), then a split
  /// of the slab around it: [t0, a], [a, b], [b, t1] with b - a = 2g and g a power of two no
  /// larger than half the distance at that time over the speed (so the middle slab moves less
  /// than the distance: excluded by the closest direction), or, near a contact, g at most
  /// delta / (2 speed) (so that a is accepted). False when no useful split was found.
  bool jump(const Box& bx) {
    const double t0 = bx.lo[0], t1 = bx.hi[0];
    double t = 0.5 * (t0 + t1), u, v, r[3], rt[3];
    for (int it = 0; it < 6; ++it) {
      closest(t, u, v, r, rt);
      const double vv = rt[0] * rt[0] + rt[1] * rt[1] + rt[2] * rt[2];
      if (!(vv > 0.0)) return false;
      const double next = std::min(t1, std::max(t0, t - (r[0] * rt[0] + r[1] * rt[1] + r[2] * rt[2]) / vv));
      const bool done = std::fabs(next - t) <= 0x1p-40 * (t1 - t0);
      t = next;
      if (done) break;
    }
    closest(t, u, v, r, rt);
    const double speed = std::sqrt(rt[0] * rt[0] + rt[1] * rt[1] + rt[2] * rt[2]);
    const double dist = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    const double reach = std::max(0.5 * delta_, 0.5 * dist);
    if (!(speed > 0.0) || !(reach / speed >= 0x1p-44)) return false;
    int e = 0;
    std::frexp(reach / speed, &e);
    const double g = std::ldexp(1.0, e - 1);  // a power of two <= reach / speed
    const double a = std::floor(t / g) * g - g, b = a + 3.0 * g;
    if (!(a > t0 + 0x1p-6 * (t1 - t0) || b < t1 - 0x1p-6 * (t1 - t0))) return false;
    // Latest first on the stack: [b, t1], [a, b], [t0, a].
    if (b < t1) stack_->push_back({{std::max(b, t0), 0.0, 0.0}, {t1, 1.0, 1.0}, true});
    stack_->push_back({{std::max(a, t0), 0.0, 0.0}, {std::min(b, t1), 1.0, 1.0}, true});
    if (a > t0) stack_->push_back({{t0, 0.0, 0.0}, {a, 1.0, 1.0}, true});
    return true;
  }

  /// A general box: exclusion, acceptance (small image, or a certified small distance at the
  /// box's lower time), else split along the parameter that changes F most.
  void general(const Box& b) {
    double f[8][3], lo[3], hi[3];
    corner_values(m_, b, vf_, f);
    if (excluded(m_, b, f, lo, hi)) return;
    const int axis = split_axis(b, f);
    const double accept_width = 0.5 * delta_;
    if (axis < 0 || (hi[0] - lo[0] <= accept_width && hi[1] - lo[1] <= accept_width && hi[2] - lo[2] <= accept_width))
      return accept(b.lo[0]);
    const double mid = 0.5 * (b.lo[axis] + b.hi[axis]);
    Box left = b, right = b;
    left.hi[axis] = mid;
    right.lo[axis] = mid;
    // The later (or upper) half first onto the stack, so that the earlier half is taken next.
    for (const Box* child : {&right, &left})
      if (!(vf_ && child->lo[1] + child->lo[2] > 1.0)) stack_->push_back(*child);
  }

  const Motion m_;
  const bool vf_;
  const double delta_, tau_;
  const int max_boxes_;
  std::vector<Box>* stack_ = nullptr;
  CcdInclusionResult r_;
  double best_ = 1.0;
  int slabs_ = 0;
};

}  // namespace

CcdInclusionResult ccd_inclusion_search(const CcdSystem& s, double t_lo, double t_hi, double delta, double tau,
                                        int max_boxes) {
  InclusionSearch search(s, delta, tau, max_boxes);
  return search.run(t_lo, t_hi);
}

}  // namespace tecido
