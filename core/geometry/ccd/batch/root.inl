/// The decisions core's continuous collision test (ccd.h) takes at the root of its time search,
/// [0, 1], on a block of queries, one per lane: the order of time_search.cpp's root visit with
/// its arithmetic, which is decisions.inl's text, the same the scalar search runs at width 1
/// (core's default settings). A lane gets "miss" or "hit" only where the time search takes that
/// decision at its root; everything else is left to ccd itself ("open"). In ccd's order:
///  1. the coplanarity cubic with its permanent bound (the cheap bound has already failed for
///     these queries, so ccd computes this one): certainly nonzero on [0, 1] is a miss (rule 1);
///  2. the projected quadratics and rule 2 at the root: den of certain sign and some numerator
///     certainly of the opposite sign is a miss; numerators of den's sign are "inside";
///  3. rule J at the root: the cubic certainly monotone with a sign change, its root
///     approximated (cubic_root), a bracket certified (certify_bracket). With every numerator
///     inside (ccd goes through refine() then) a certified bracket is a hit; otherwise the
///     quadratics restricted to the bracket decide (bracket_decision).
/// Not applicable rule J, no certified bracket: open (ccd goes on splitting [0, 1]).
/// Only the decision is taken here, not the time of impact.
// A per-width file (core/simd/target.h), included by kernels.inl. No include guard, no
// includes, no namespace.

/// system.cpp's differences X, Y, Z, P, Q at both times (its kPairs, unscaled: the caller
/// checked the range).
template <class S, int K>
TECIDO_SIMD_INLINE void differences(const Points<S>& p, V3<S> (&d)[2][5]) {
  constexpr int kPairs[2][5][2] = {{{2, 1}, {3, 1}, {0, 1}, {2, 0}, {3, 0}}, {{1, 0}, {2, 3}, {2, 0}, {1, 2}, {0, 3}}};
  for (int t = 0; t < 2; ++t) {
    for (int v = 0; v < 5; ++v) {
      const int a = kPairs[K][v][0], b = kPairs[K][v][1];
      d[t][v] = {p.p[t][a][0] - p.p[t][b][0], p.p[t][a][1] - p.p[t][b][1], p.p[t][a][2] - p.p[t][b][2]};
    }
  }
}

/// The root decisions for the lanes of `lanes` (kind K: 0 vertex-face, 1 edge-edge): bits of
/// the lanes ccd answers miss, and hit, at its time search's root.
template <class S, int K>
TECIDO_SIMD_INLINE void root_decisions(const Points<S>& pts, unsigned lanes, unsigned& miss, unsigned& hit) {
  using V = typename S::V;
  using M = typename S::K;
  constexpr int kCount = K == 0 ? 4 : 5;  // den and the numerators
  // (U, V) vector pairs of the quadratics, den first (projected_quadratics.cpp).
  constexpr int kUV[2][5][2] = {{{0, 1}, {2, 1}, {0, 2}, {3, 4}, {3, 4}}, {{0, 1}, {2, 1}, {0, 2}, {3, 1}, {0, 4}}};
  const CcdSettings defaults;
  const V zero = S::set1(0.0), one = S::set1(1.0);
  V3<S> d[2][5];
  differences<S, K>(pts, d);
  V f[4];
  cubic_coefficients<S>(d[0][0], d[1][0], d[0][1], d[1][1], d[0][2], d[1][2], f);
  const V ef = cubic_permanent_bound<S>(d[0][0], d[1][0], d[0][1], d[1][1], d[0][2], d[1][2]);
  const V ef_step = bound_step<S>(largest_abs<S>(f, 4), ef);
  M pos, neg;
  certified_sign<S>(f, 4, ef, pos, neg);
  miss = lanes & S::bits(S::kor(pos, neg));  // rule 1
  hit = 0;
  lanes &= ~miss;
  if (!lanes) return;
  const Projection<S> pr = projection<S>(d[0][0], d[1][0], d[0][1], d[1][1]);
  V q[5][3], e0[5], e1[5];
  for (int k = 0; k < kCount; ++k) {
    V step;
    projected_quadratic<S>(pr, d[0][kUV[K][k][0]], d[1][kUV[K][k][0]], d[0][kUV[K][k][1]], d[1][kUV[K][k][1]], q[k],
                           e0[k], step);
    e1[k] = e0[k] + step;  // the bound one level down
  }
  DenKnown<S> kn;
  for (M& in : kn.inside) in = S::none();
  certified_sign<S>(q[0], 3, e0[0], kn.dpos, kn.dneg);
  kn.sd = sign_value<S>(kn.dpos, kn.dneg);
  kn.den_low = vmin<S>(vmin<S>(kn.sd * q[0][0], kn.sd * q[0][1]), kn.sd * q[0][2]) - e0[0];
  M opposite = S::none(), all_inside = S::kor(kn.dpos, kn.dneg);
  for (int k = 1; k < kCount; ++k) {
    certified_sign<S>(q[k], 3, e0[k], pos, neg);
    opposite = S::kor(opposite, S::kor(S::kand(kn.dpos, neg), S::kand(kn.dneg, pos)));
    kn.inside[k] = S::kor(S::kand(kn.dpos, pos), S::kand(kn.dneg, neg));
    all_inside = S::kand(all_inside, kn.inside[k]);
  }
  const unsigned rule2 = lanes & S::bits(opposite);
  miss |= rule2;
  lanes &= ~rule2;
  V s0;
  lanes &= S::bits(monotone_crossing<S>(f, ef, s0));  // rule J applicable
  if (!lanes) return;
  const V tr = zero + cubic_root<S>(f, S::set1(0x1p-48)) * one;  // lo + root * w on [0, 1]
  V a, b, sa, sb;
  const unsigned bracketed = lanes & S::bits(certify_bracket<S>(f, tr, zero, one, 1.0, ef + ef_step, s0,
                                                                0.25 * defaults.time_tolerance, lanes, a, b, sa, sb));
  const unsigned refined = S::bits(all_inside);
  hit |= bracketed & refined;  // every numerator inside: refine()'s jump, a hit at the bracket
  const unsigned rest = bracketed & ~refined;
  if (!rest) return;
  M m, h, open;
  bracket_decision<S>(q, e1, kCount, kn, sa, sb, defaults.distance_tolerance / 27.72, m, h, open);
  miss |= rest & S::bits(m);
  hit |= rest & S::bits(h);
}
