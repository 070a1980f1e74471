#pragma once
/// The fixed benchmark input for continuous collision tests: a seeded, reproducible mix of
/// vertex-face or edge-edge queries (core/geometry/ccd/query.h), shared by the core and the
/// reference-engine benchmarks so that every engine times identical queries.
///
/// Generator: std::mt19937_64, each double from the top 53 bits of one draw ((x >> 11) 2^-53,
/// not std::uniform_real_distribution, whose output differs between standard libraries);
/// query k of the mix is category k % 20 in the table below (so every prefix is mixed), drawn
/// in order from one generator seeded `seed`. Sizes are about 1 (points in the unit cube).
///
/// | share | category      | what                                                                  |
/// |-------|---------------|-----------------------------------------------------------------------|
/// | 4/20  | random-large  | all 8 points uniform in [0,1]^3, t = 0 and t = 1 independent          |
/// | 6/20  | random-small  | points uniform in [0,1]^3 at t = 0, each moved by up to 0.1 per axis  |
/// |       |               | (the shape of a cloth's broad-phase candidates)                       |
/// | 3/20  | contact       | a contact built at a chosen time, point and (u, v), random motions    |
/// | 3/20  | near-miss     | the same, the contact point moved off the face past an edge, in its   |
/// |       |               | plane (or the second edge slid along its line to start past the       |
/// |       |               | crossing) by 10^-k, k uniform in [2, 12]: a miss at t*, though the    |
/// |       |               | random motions may still bring the primitives together at other times |
/// | 2/20  | coplanar      | random-small flattened onto the plane z = 0.5 at both times           |
/// | 2/20  | degenerate    | in turn: parallel edges / zero-area triangle, a zero-length edge /    |
/// |       |               | a vertex sliding along an edge, contact exactly at t = 0, at t = 1,   |
/// |       |               | collinear edges / a vertex on an edge's line, all on dyadic values    |
#include "core/geometry/ccd/query.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace tecido::bench {

struct LabelledCcdQuery {
  CcdQuery query;
  const char* category;
};

inline constexpr std::size_t kDefaultCcdQueryCount = 20000;
inline constexpr std::uint64_t kDefaultCcdQuerySeed = 2021;

namespace ccd_queries_detail {

class Draw {
 public:
  explicit Draw(std::uint64_t seed) : rng_(seed) {}
  double unit() { return static_cast<double>(rng_() >> 11) * 0x1.0p-53; }
  double range(double lo, double hi) { return lo + (hi - lo) * unit(); }
  Vec3 point() {
    const double x = unit(), y = unit(), z = unit();
    return Vec3(x, y, z);
  }
  Vec3 offset(double r) {
    const double x = range(-r, r), y = range(-r, r), z = range(-r, r);
    return Vec3(x, y, z);
  }
  int index(int n) { return static_cast<int>(rng_() % static_cast<std::uint64_t>(n)); }

 private:
  std::mt19937_64 rng_;
};

/// Points at time t* given; each moves with its own velocity so that it is there at t*.
inline CcdQuery through(CcdKind kind, const std::array<Vec3, 4>& at, double ts, Draw& d, double speed) {
  CcdQuery q;
  q.kind = kind;
  for (int i = 0; i < 4; ++i) {
    const Vec3 v = d.offset(speed);
    q.x0[i] = at[i] - ts * v;
    q.x1[i] = at[i] + (1.0 - ts) * v;
  }
  return q;
}

/// A contact at time t* (vertex in the face at (u, v), or the edges crossing at (u, v)); with
/// miss > 0 the contact point is moved off the face past an edge (vertex-face), or the second
/// edge along its line to start past the crossing point (edge-edge), by `miss`.
inline CcdQuery built_contact(CcdKind kind, Draw& d, double miss) {
  const double ts = d.unit();
  std::array<Vec3, 4> at;
  if (kind == CcdKind::VertexFace) {
    at[1] = d.point();
    at[2] = d.point();
    at[3] = d.point();
    const double u = d.range(0.05, 0.9), v = d.range(0.05, 0.95 - u);
    at[0] = at[1] + u * (at[2] - at[1]) + v * (at[3] - at[1]);
    if (miss > 0) {
      // Past edge b-c: from the point on bc nearest the contact, outward in the plane.
      const Vec3 n = (at[2] - at[1]).cross(at[3] - at[1]);
      const Vec3 out = (at[3] - at[2]).cross(n).normalized();
      const double s = u / (u + v);
      at[0] = at[2] + s * (at[3] - at[2]) + miss * out;
    }
  } else {
    const Vec3 c = d.point();
    const Vec3 ea = d.offset(0.5), eb = d.offset(0.5);
    const double u = d.unit(), v = d.unit();
    at[0] = c - u * ea;
    at[1] = c + (1.0 - u) * ea;
    // A miss: the second edge starts `miss` past the crossing point, along its own line.
    const Vec3 b0 = miss > 0 ? Vec3(c + miss * eb.normalized()) : Vec3(c - v * eb);
    at[2] = b0;
    at[3] = b0 + eb;
  }
  return through(kind, at, ts, d, 0.5);
}

/// The degenerate family, case `which` (0..4), on dyadic values so the construction is exact.
inline CcdQuery degenerate(CcdKind kind, Draw& d, int which) {
  // Dyadic values: multiples of 1/64 in [0, 1].
  auto dy = [&d] { return static_cast<double>(d.index(65)) / 64.0; };
  auto dyp = [&] { return Vec3(dy(), dy(), dy()); };
  CcdQuery q;
  q.kind = kind;
  const Vec3 move = dyp() - Vec3(0.5, 0.5, 0.5);
  if (kind == CcdKind::EdgeEdge) {
    const Vec3 a0 = dyp(), e = dyp() - Vec3(0.5, 0.5, 0.5);
    switch (which) {
      case 0: {  // parallel edges, the second moving across the first's line
        const Vec3 b0 = dyp();
        q.x0 = {a0, a0 + e, b0, b0 + 0.5 * e};
        q.x1 = {a0, a0 + e, b0 + move, b0 + move + 0.5 * e};
        break;
      }
      case 1: {  // a zero-length edge (a point) against a moving edge
        const Vec3 b0 = dyp(), f = dyp();
        q.x0 = {a0, a0, b0, f};
        q.x1 = {a0 + move, a0 + move, b0, f};
        break;
      }
      case 2:  // contact exactly at t = 0: the edges cross at their midpoints
      case 3: {  // ... or exactly at t = 1
        const Vec3 f = dyp() - Vec3(0.5, 0.5, 0.5);
        const std::array<Vec3, 4> at = {a0 - 0.5 * e, a0 + 0.5 * e, a0 - 0.5 * f, a0 + 0.5 * f};
        q.x0 = at;
        q.x1 = at;
        for (int i = 0; i < 4; ++i) (which == 2 ? q.x1 : q.x0)[i] += (i < 2 ? move : -move);
        break;
      }
      default: {  // collinear edges sliding along one line
        q.x0 = {a0, a0 + e, a0 + 2.0 * e, a0 + 3.0 * e};
        q.x1 = {a0, a0 + e, a0 + 0.5 * e, a0 + 1.5 * e};
        break;
      }
    }
  } else {
    const Vec3 a = dyp(), b = dyp(), c = dyp();
    switch (which) {
      case 0: {  // zero-area triangle (c on segment ab) with the vertex crossing it
        const Vec3 mid = 0.5 * (a + b);
        q.x0 = {mid + move, a, b, 0.25 * a + 0.75 * b};
        q.x1 = {mid - move, a, b, 0.25 * a + 0.75 * b};
        break;
      }
      case 1: {  // a vertex sliding along the edge ab
        q.x0 = {a, a, b, c};
        q.x1 = {b, a, b, c};
        break;
      }
      case 2:  // contact exactly at t = 0 (vertex at the centroid-ish point a/2 + b/4 + c/4)
      case 3: {  // ... or exactly at t = 1
        const Vec3 p = 0.5 * a + 0.25 * b + 0.25 * c;
        q.x0 = {p, a, b, c};
        q.x1 = {p, a, b, c};
        (which == 2 ? q.x1 : q.x0)[0] += move;
        break;
      }
      default: {  // the vertex moving along the line of edge ab, past b
        q.x0 = {2.0 * b - a, a, b, c};
        q.x1 = {3.0 * b - 2.0 * a, a, b, c};
        break;
      }
    }
  }
  return q;
}

}  // namespace ccd_queries_detail

/// The category of query k of the mix.
inline const char* ccd_mix_category(std::size_t k) {
  static const char* const table[20] = {"random-large", "random-small", "contact",      "random-small", "near-miss",
                                        "random-large", "random-small", "coplanar",     "contact",      "random-small",
                                        "near-miss",    "random-large", "degenerate",   "random-small", "contact",
                                        "random-small", "near-miss",    "random-large", "coplanar",     "degenerate"};
  return table[k % 20];
}

/// `count` queries of `kind` in the mix above, from `seed`.
inline std::vector<LabelledCcdQuery> ccd_query_mix(CcdKind kind, std::size_t count = kDefaultCcdQueryCount,
                                                   std::uint64_t seed = kDefaultCcdQuerySeed) {
  using namespace ccd_queries_detail;
  Draw d(seed);
  std::vector<LabelledCcdQuery> out;
  out.reserve(count);
  int degenerate_case = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const std::string cat = ccd_mix_category(k);
    CcdQuery q;
    q.kind = kind;
    if (cat == "random-large") {
      for (int i = 0; i < 4; ++i) q.x0[i] = d.point();
      for (int i = 0; i < 4; ++i) q.x1[i] = d.point();
    } else if (cat == "random-small" || cat == "coplanar") {
      for (int i = 0; i < 4; ++i) q.x0[i] = d.point();
      for (int i = 0; i < 4; ++i) q.x1[i] = q.x0[i] + d.offset(0.1);
      if (cat == "coplanar")
        for (int i = 0; i < 4; ++i) q.x0[i].z() = q.x1[i].z() = 0.5;
    } else if (cat == "contact") {
      q = built_contact(kind, d, 0.0);
    } else if (cat == "near-miss") {
      q = built_contact(kind, d, std::pow(10.0, -d.range(2.0, 12.0)));
    } else {
      q = degenerate(kind, d, degenerate_case++ % 5);
    }
    out.push_back({q, ccd_mix_category(k)});
  }
  return out;
}

/// The default mix of one kind, generated once per process.
inline const std::vector<LabelledCcdQuery>& default_ccd_query_mix(CcdKind kind) {
  static const std::vector<LabelledCcdQuery> vf = ccd_query_mix(CcdKind::VertexFace);
  static const std::vector<LabelledCcdQuery> ee = ccd_query_mix(CcdKind::EdgeEdge);
  return kind == CcdKind::VertexFace ? vf : ee;
}

}  // namespace tecido::bench
