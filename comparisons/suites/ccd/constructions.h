#pragma once
/// Building blocks of the ccd suite's families: queries whose answer is known by construction.
///
/// Every construction works on small dyadic rationals (integers over a power of two, a few bits
/// each), so that every coordinate the generators compute is exact in double precision and the
/// constructed contact is a real contact of the doubles. Answers survive three exact
/// transformations, used to move the constructions off the axes:
///  - an invertible affine map with dyadic entries (contact, and its time, are affine-invariant:
///    linear motion stays linear and incidence is kept);
///  - relabelling (a triangle's corners in any order; an edge's ends swapped; the two edges
///    swapped): the closed primitives are the same sets;
///  - scaling by a power of two and translating by a dyadic offset (while no bit is lost).
#include "comparisons/suites/random.h"
#include "core/geometry/ccd/query.h"

#include <array>
#include <vector>

namespace tecido::suites::ccd {

/// A query and, when the family constructs it, its answer.
struct KnownQuery {
  CcdQuery q;
  /// -1 unknown (the referee decides), 0 a miss, 1 a hit.
  int known = -1;
  /// The first time of contact when known == 1: a dyadic rational, exact.
  double toi = 0.0;
};

/// k / den with k uniform in [lo, hi].
double dyadic(Rng& r, int lo, int hi, int den);
/// A vector of three dyadic(r, -m, m, den).
Vec3 dyadic_vec(Rng& r, int m, int den);

/// The query whose points are at `at` at time t and move with velocities v:
/// x0 = at - t v, x1 = at + (1 - t) v.
CcdQuery moving_through(CcdKind kind, double t, const std::array<Vec3, 4>& at, const std::array<Vec3, 4>& v);

/// `count` queries of `kind` with unknown answers (the referee decides): points uniform in the unit
/// cube at t = 0; at t = 1 uniform again (even k) or moved by at most `small_motion` per axis (odd k).
void random_motion(CcdKind kind, Rng& r, double small_motion, std::size_t count, std::vector<KnownQuery>& out);

/// A hit at t (known = 1) or a miss (known = 0).
KnownQuery known_hit(const CcdQuery& q, double t);
KnownQuery known_miss(const CcdQuery& q);

/// An invertible affine map x -> m x + o: m's entries multiples of 1/8 in [-1, 1], o's of 1/64 in
/// [-1, 1], |det m| >= 1/8 (exact on the constructions' coordinates).
struct Affine {
  std::array<Vec3, 3> rows;
  Vec3 o;
};
Affine random_affine(Rng& r);
/// The query with every point mapped.
CcdQuery mapped(const CcdQuery& q, const Affine& a);

/// A plane embedding (u, v) -> o + u e1 + v e2 with dyadic o, e1, e2 and e1 x e2 != 0, for the
/// constructions drawn in a plane.
struct PlaneFrame {
  Vec3 o, e1, e2;
  Vec3 at(double u, double v) const { return o + u * e1 + v * e2; }
};
PlaneFrame random_plane(Rng& r);

/// The axes permuted and their signs flipped at random (exact for any coordinates).
CcdQuery permuted_axes(const CcdQuery& q, Rng& r);

/// The primitives relabelled at random: a triangle's corners in any order; each edge's ends
/// swapped and the two edges swapped at random. The answer does not change.
CcdQuery relabelled(const CcdQuery& q, Rng& r);

/// Every coordinate times 2^e.
CcdQuery scaled(const CcdQuery& q, int e);
/// Every point moved by d.
CcdQuery translated(const CcdQuery& q, const Vec3& d);

/// `count` queries of `generic(r)`, the k-th multiplied by 2^scale[k % n] or, past the scales, moved
/// by +-2^offset along each axis (n: both lists' sizes); both exact, so each answer stands.
void rescaled_queries(Rng& r, KnownQuery (*generic)(Rng&), const std::vector<int>& scale,
                      const std::vector<int>& offset, std::size_t count, std::vector<KnownQuery>& out);

}  // namespace tecido::suites::ccd
