#include "comparisons/suites/plane/categories.h"

#include <cmath>

namespace tecido::suites::plane {

// Where one expression used to take several draws, the draws below are taken one by one in the
// order that expression took them, so that every case equals the one earlier reports used.

namespace {

double sign(Rng& r) { return r.below(2) ? 1.0 : -1.0; }

BoundedPlane random_plane(Rng& r, const Vec3& centre) {
  const Vec3 n = r.unit_vector();
  Vec3 f = r.unit_vector();
  while (n.cross(f).norm() < 0.1) f = r.unit_vector();
  const double hy = r.uniform(0.1, 2.0);
  const double hx = r.uniform(0.1, 2.0);
  return make_bounded_plane(centre, n, f, Vec2(hx, hy), 0.0);
}

/// Axis-aligned plane (normal +z) at a dyadic height, centre and half extents, so that "on the
/// plane" is exactly representable.
BoundedPlane flat_plane(Rng& r) {
  const double z = std::ldexp(static_cast<double>(r.below(64)) - 32.0, -3);
  const Vec3 f = r.below(2) ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  const double hy = std::ldexp(1.0 + static_cast<double>(r.below(8)), -2);
  const double hx = std::ldexp(1.0 + static_cast<double>(r.below(8)), -2);
  const double x = std::ldexp(static_cast<double>(r.below(16)), -2);
  return make_bounded_plane(Vec3(x, 0.5, z), Vec3(0, 0, 1), f, Vec2(hx, hy), 0.0);
}

/// A point uniform in [x0, x1] x [y0, y1] at height z (y drawn first).
Vec3 flat_point(Rng& r, double x0, double x1, double y0, double y1, double z) {
  const double y = r.uniform(y0, y1);
  return Vec3(r.uniform(x0, x1), y, z);
}

/// A segment through point c along a direction whose sine with the plane is at least 0.2.
io::PlaneCase through(Rng& r, const BoundedPlane& p, const Vec3& c) {
  Vec3 d = r.unit_vector();
  if (std::abs(d.dot(p.normal)) < 0.2) d += p.normal;
  const double a = r.uniform(0.05, 1.5), b = r.uniform(0.05, 1.5);
  return {"", p, c - a * d, c + b * d, {}};
}

/// random_case at `offset` from the origin (0: the random category itself).
io::PlaneCase box_case(Rng& r, double offset) {
  const Vec3 shift = offset * r.unit_vector();
  const BoundedPlane p = random_plane(r, shift + r.in_box(-0.5, 0.5));
  const Vec3 to = shift + r.in_box(-2.5, 2.5);
  return {"", p, shift + r.in_box(-2.5, 2.5), to, {}};
}

}  // namespace

/// A random plane through a point in [-0.5, 0.5]^3 and a segment between two points in
/// [-2.5, 2.5]^3; the plane's normal and forward are random unit vectors, half extents in [0.1, 2].
io::PlaneCase random_case(Rng& r, long) { return box_case(r, 0.0); }

/// random_case shifted 10^(3 + k mod 6) m from the origin in a random direction.
io::PlaneCase far_case(Rng& r, long k) { return box_case(r, std::pow(10.0, 3 + static_cast<double>(k % 6))); }

/// A segment through a point on one of the rectangle's four edges (up to one rounding), crossing
/// the plane steeply (the sine of its angle to the plane is at least 0.2).
io::PlaneCase edge_case(Rng& r, long) {
  const BoundedPlane p = random_plane(r, r.in_box(-1, 1));
  const double s = sign(r);
  const double hx = p.half_extents.x(), hy = p.half_extents.y();
  const Vec3 c = r.below(2) ? p.position + s * hx * p.forward + r.uniform(-1, 1) * hy * p.right()
                            : p.position + r.uniform(-1, 1) * hx * p.forward + s * hy * p.right();
  return through(r, p, c);
}

/// The same through one of the four corners.
io::PlaneCase corner_case(Rng& r, long) {
  const BoundedPlane p = random_plane(r, r.in_box(-1, 1));
  const double sy = sign(r);
  const double sx = sign(r);
  return through(r, p, p.position + sx * p.half_extents.x() * p.forward + sy * p.half_extents.y() * p.right());
}

/// A segment at an angle of 1e-12 .. 1e-3 rad to the plane, through a point of the plane within 1.2
/// half extents of the centre (so some cross the rectangle, some pass beside it).
io::PlaneCase grazing_case(Rng& r, long) {
  const BoundedPlane p = random_plane(r, r.in_box(-1, 1));
  const double cy = r.uniform(-1.2, 1.2);
  const double cx = r.uniform(-1.2, 1.2);
  const Vec3 c = p.position + cx * p.half_extents.x() * p.forward + cy * p.half_extents.y() * p.right();
  const double ty = r.uniform(-1, 1);
  const Vec3 t = (r.uniform(-1, 1) * p.forward + ty * p.right()).normalized();
  const double tilt = std::pow(10.0, r.uniform(-12, -3));
  const Vec3 d = (t + tilt * sign(r) * p.normal).normalized();
  const double a = r.uniform(0.1, 1.0), b = r.uniform(0.1, 1.0);
  return {"", p, c - a * d, c + b * d, {}};
}

/// On an axis-aligned plane at a dyadic height (flat_plane): a segment parallel to it, 1 .. 2^-39
/// above or below, exactly.
io::PlaneCase parallel_case(Rng& r, long) {
  const BoundedPlane p = flat_plane(r);
  const double dz = std::ldexp(1.0, -static_cast<int>(r.below(40)));  // 1 down to 2^-39
  const double z = p.position.z() + sign(r) * dz;
  const Vec3 to = flat_point(r, -3, 3, -3, 3, z);
  return {"", p, flat_point(r, -3, 3, -3, 3, z), to, {}};
}

/// On such a plane: a segment lying exactly in it, inside, across or beside the rectangle.
io::PlaneCase in_plane_case(Rng& r, long) {
  const BoundedPlane p = flat_plane(r);
  const double z = p.position.z();
  const Vec3 to = flat_point(r, -2, 3, -1.5, 2.5, z);
  return {"", p, flat_point(r, -2, 3, -1.5, 2.5, z), to, {}};
}

namespace {
/// A point exactly on the flat plane and one 0.01 .. 1 m above or below it (x and y within 1 m).
std::pair<Vec3, Vec3> on_and_off(Rng& r, const BoundedPlane& p) {
  const Vec3 on = flat_point(r, -2, 3, -1.5, 2.5, p.position.z());
  const double size = r.uniform(0.01, 1);
  const double dz = size * sign(r);
  const double dy = r.uniform(-1, 1);
  return {on, on + Vec3(r.uniform(-1, 1), dy, dz)};
}
}  // namespace

/// On such a plane: a segment whose first end point lies exactly on the plane.
io::PlaneCase start_on_case(Rng& r, long) {
  const BoundedPlane p = flat_plane(r);
  const auto [on, off] = on_and_off(r, p);
  return {"", p, on, off, {}};
}

/// On such a plane: a segment whose second end point lies exactly on the plane.
io::PlaneCase end_on_case(Rng& r, long) {
  const BoundedPlane p = flat_plane(r);
  const auto [on, off] = on_and_off(r, p);
  return {"", p, off, on, {}};
}

const std::vector<Category>& categories() {
  static const std::vector<Category> table = {
      {"random", "a random plane and segment (points uniform in a box 5 m wide)", &random_case, true},
      {"edge", "crossing on one of the rectangle's edges, up to one rounding", &edge_case},
      {"corner", "crossing at one of the rectangle's corners, up to one rounding", &corner_case},
      {"grazing", "at 1e-12 .. 1e-3 rad to the plane", &grazing_case},
      {"parallel", "exactly parallel to an axis-aligned plane, 1 m .. 2^-39 m off it", &parallel_case},
      {"in-plane", "lying exactly in an axis-aligned plane", &in_plane_case},
      {"start-on", "first end point exactly on an axis-aligned plane", &start_on_case},
      {"end-on", "second end point exactly on an axis-aligned plane", &end_on_case},
      {"far", "random cases 10^3 .. 10^8 m from the origin", &far_case},
  };
  return table;
}

io::PlaneCase category_case(std::uint64_t seed, std::size_t c, const Category& category, long k) {
  return agreement::family_case(category, Rng(substream(seed, c * 100000000ULL + static_cast<std::uint64_t>(k))), k);
}

std::string case_category(const std::string& id) { return id.substr(0, id.find('/')); }

}  // namespace tecido::suites::plane
