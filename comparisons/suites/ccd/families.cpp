#include "comparisons/suites/ccd/families.h"

#include <stdexcept>

namespace tecido::suites::ccd {

std::string family_name(const Family& f) { return std::string(ccd_kind_name(f.kind)) + "/" + f.name; }

const std::vector<Family>& families() {
  constexpr CcdKind VF = CcdKind::VertexFace, EE = CcdKind::EdgeEdge;
  static const std::vector<Family> table = {
      {"random", VF, &vf_random, "random motion in the unit cube: half anywhere, half small steps", false, true},
      {"crossing", VF, &vf_crossing, "vertex through the triangle's plane at a generic time, inside or outside"},
      {"spike", VF, &vf_spike, "vertex exactly through an edge (both triangles of the crack) or a corner, or just past one (a hole)"},
      {"sliding", VF, &vf_sliding, "coplanar throughout: sliding inside, entering through an edge at t, sliding beside an edge"},
      {"parallel", VF, &vf_parallel, "vertex at a height (down to 2^-30) moving parallel to the triangle's plane"},
      {"degenerate", VF, &vf_degenerate, "zero-area triangles (collinear corners, repeated corners, a point) crossed or missed"},
      {"endpoints", VF, &vf_endpoints, "contact exactly at t = 0 or t = 1, or just outside the step"},
      {"near-miss", VF, &vf_near_miss, "vertex passing an edge by 1-4 units of 2^-52 inside (hit) or outside (miss)"},
      {"scale", VF, &vf_scale, "crossings scaled by 2^-1000 .. 2^1000 or moved by 2^10 .. 2^39"},
      {"random", EE, &ee_random, "random motion in the unit cube: half anywhere, half small steps", false, true},
      {"crossing", EE, &ee_crossing, "edges' lines meeting at a generic time, on or off the edges"},
      {"crack", EE, &ee_crack, "lines meeting exactly at an edge's end (or both ends), or just past one"},
      {"sliding", EE, &ee_sliding, "collinear edges sliding into contact or overlapping, crossing edges sliding, parallel ones apart"},
      {"wedge", EE, &ee_wedge, "a ridge coming down onto a parallel edge: overlapping, end to end, or beside it"},
      {"coplanar", EE, &ee_coplanar, "coplanar throughout: an edge moving onto another within their plane, or past its end"},
      {"parallel", EE, &ee_parallel, "parallel lines or parallel planes at a distance (down to 2^-30), moving along them"},
      {"degenerate", EE, &ee_degenerate, "zero-length edges: a point crossing or missing a segment, two points meeting or passing"},
      {"endpoints", EE, &ee_endpoints, "crossing exactly at t = 0 or t = 1, or just outside the step"},
      {"near-miss", EE, &ee_near_miss, "an edge passing another's end, or ending at it, within 1-4 units of 2^-52"},
      {"scale", EE, &ee_scale, "crossings scaled by 2^-1000 .. 2^1000 or moved by 2^10 .. 2^39"},
  };
  return table;
}

std::vector<KnownQuery> family_queries(std::size_t index, const Settings& s, std::uint64_t seed) {
  const Family& f = families().at(index);
  Rng r(substream(seed, 1000 + index));
  std::vector<KnownQuery> out;
  const std::size_t count = f.constructed ? s.per_family : s.random_per_family;
  out.reserve(count);
  f.generate(r, s, count, out);
  if (out.size() != count) throw std::logic_error("ccd family " + family_name(f) + " made a wrong count");
  for (KnownQuery& kq : out) kq.q = relabelled(kq.q, r);
  return out;
}

}  // namespace tecido::suites::ccd
