#pragma once
/// The `plane` suite's categories of segment-versus-bounded-plane cases: uniform random cases and
/// adversarial ones built to sit exactly where a floating-point test decides by rounding (a
/// crossing on the rectangle's edge or corner, a segment grazing the plane, parallel to it, lying
/// in it, starting or ending on it, far from the origin).
///
/// Case k of category c is a pure function of (seed, c, k): each case draws from its own
/// substream, so any case can be regenerated alone (a sweep case, the disagreement file) and the
/// cases do not depend on how they are cut into blocks.
#include "comparisons/io/plane_cases.h"
#include "comparisons/suites/random.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tecido::suites::plane {

/// Draws case k of a category from its generator `r` (id left empty).
using CaseGenerator = io::PlaneCase (*)(Rng& r, long k);

struct Category {
  std::string name;   ///< "random", "edge", ... (case ids are "<name>/<k>")
  std::string about;  ///< one line: what the category claims about its cases
  CaseGenerator make;
  bool random = false;  ///< the uniform category: its count is Settings::random_cases and speed is timed on it
};

/// A random plane through a point in [-0.5, 0.5]^3 and a segment between two points in
/// [-2.5, 2.5]^3; the plane's normal and forward are random unit vectors, half extents in [0.1, 2].
io::PlaneCase random_case(Rng& r, long k);
/// A segment through a point on one of the rectangle's four edges (up to one rounding), crossing
/// the plane steeply (the sine of its angle to the plane is at least 0.2).
io::PlaneCase edge_case(Rng& r, long k);
/// The same through one of the four corners.
io::PlaneCase corner_case(Rng& r, long k);
/// A segment at an angle of 1e-12 .. 1e-3 rad to the plane, through a point of the plane within 1.2
/// half extents of the centre (so some cross the rectangle, some pass beside it).
io::PlaneCase grazing_case(Rng& r, long k);
/// On an axis-aligned plane at a dyadic height (flat_plane): a segment parallel to it, 1 .. 2^-39
/// above or below, exactly.
io::PlaneCase parallel_case(Rng& r, long k);
/// On such a plane: a segment lying exactly in it, inside, across or beside the rectangle.
io::PlaneCase in_plane_case(Rng& r, long k);
/// On such a plane: a segment whose first end point lies exactly on the plane.
io::PlaneCase start_on_case(Rng& r, long k);
/// On such a plane: a segment whose second end point lies exactly on the plane.
io::PlaneCase end_on_case(Rng& r, long k);
/// random_case shifted 10^(3 + k mod 6) m from the origin in a random direction.
io::PlaneCase far_case(Rng& r, long k);

/// Every category in report order: random first, then the adversarial ones.
const std::vector<Category>& categories();

/// Case k of `category` (index `c` in its table) for `seed`, with id "<name>/<k>".
io::PlaneCase category_case(std::uint64_t seed, std::size_t c, const Category& category, long k);

/// The category part of a case id ("edge/12" -> "edge").
std::string case_category(const std::string& id);

}  // namespace tecido::suites::plane
