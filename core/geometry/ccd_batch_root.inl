/// The decisions core's continuous collision test (ccd.h) takes at the root of its time search,
/// [0, 1], replayed on a block of queries, one per SIMD lane (ccd_batch_simd.h): internal to
/// ccd_batch_stages.cpp, which runs them on the queries its first stages leave open.
///
/// A lane gets "miss" or "hit" only where ccd's own time search (ccd_time_search.cpp, with the
/// default settings) takes that decision at its root, by the same operations on the same
/// doubles in the same order; everything else is left to ccd itself ("open"). Replayed, in
/// ccd's order:
///  1. the coplanarity cubic with its permanent bound (ccd_coplanarity_cubic.cpp: the cheap
///     bound has already failed for these queries, so ccd computes this one): certainly
///     nonzero on [0, 1] is a miss (rule 1);
///  2. the projected quadratics (ccd_projected_quadratics.cpp: the projection axis, the
///     coefficients and their bounds) and rule 2 at the root: den of certain sign and some
///     numerator certainly of the opposite sign is a miss; numerators of den's sign are
///     "inside";
///  3. rule J at the root (TimeSearch::jump): the cubic certainly monotone with a sign change,
///     its root approximated by ccd_cubic_root's safeguarded Newton iteration, brackets of
///     width 3h tried for h = 2^-46, 2^-42, ..., 2^-22 until the restricted cubic certifies one.
///     With every numerator inside (ccd goes through refine() then) a certified bracket is a
///     hit. Otherwise the quadratics restricted to the bracket decide: a numerator certainly of
///     the opposite sign is a miss, every numerator within beta of inside a hit; den without a
///     certain sign there, or neither, goes to ccd's inclusion search: open.
/// Not applicable rule J, no certified bracket: open (ccd goes on splitting [0, 1]).
/// Only the decision is replayed, not the time of impact.
// Included by ccd_batch_kernels.inl only, once per width, inside that width's namespace and
// target region (ccd_batch_simd.h says why): no include guard, no includes, no namespace.

/// The five difference vectors X, Y, Z, P, Q of ccd_system.h at both times.
template <class S>
struct Differences {
  V3<S> d[2][5];
};

/// ccd_system.cpp's differences (its kPairs, unscaled: the caller checked the range).
template <class S, int K>
TECIDO_BATCH_INLINE void differences(const Points<S>& p, Differences<S>& out) {
  constexpr int kPairs[2][5][2] = {{{2, 1}, {3, 1}, {0, 1}, {2, 0}, {3, 0}}, {{1, 0}, {2, 3}, {2, 0}, {1, 2}, {0, 3}}};
  for (int t = 0; t < 2; ++t) {
    for (int v = 0; v < 5; ++v) {
      const int a = kPairs[K][v][0], b = kPairs[K][v][1];
      out.d[t][v] = {p.p[t][a][0] - p.p[t][b][0], p.p[t][a][1] - p.p[t][b][1], p.p[t][a][2] - p.p[t][b][2]};
    }
  }
}

/// A polynomial's coefficients and the bound of ccd_bernstein.h's CcdErrorBound.
template <class S, int N>
struct Bernstein {
  typename S::V c[N];
  typename S::V e0, step;
};

/// The lanes where every coefficient exceeds e (sign +1) or is below -e (sign -1): the two
/// masks of ccd_certified_sign.
template <class S, int N>
TECIDO_BATCH_INLINE void certified_sign(const typename S::V (&c)[N], typename S::V e, typename S::K& pos,
                                        typename S::K& neg) {
  typename S::V lo = c[0], hi = c[0];
  for (int i = 1; i < N; ++i) {
    lo = S::select(S::lt(c[i], lo), c[i], lo);
    hi = S::select(S::lt(hi, c[i]), c[i], hi);
  }
  pos = S::lt(e, lo);
  neg = S::lt(hi, S::set1(0.0) - e);
}

template <class S>
TECIDO_BATCH_INLINE V3<S> cross_abs(const V3<S>& a, const V3<S>& b) {
  return {S::abs(a.y * b.z) + S::abs(a.z * b.y), S::abs(a.z * b.x) + S::abs(a.x * b.z),
          S::abs(a.x * b.y) + S::abs(a.y * b.x)};
}
template <class S>
TECIDO_BATCH_INLINE typename S::V dot_abs(const V3<S>& a, const V3<S>& b) {
  return S::abs(a.x) * b.x + S::abs(a.y) * b.y + S::abs(a.z) * b.z;
}

/// ccd_coplanarity_cubic with the permanent bound (its path when the cheap bound fails).
template <class S>
TECIDO_BATCH_INLINE void cubic_with_permanent(const Differences<S>& s, Bernstein<S, 4>& f) {
  using V = typename S::V;
  const V3<S>&x0 = s.d[0][0], &x1 = s.d[1][0], &y0 = s.d[0][1], &y1 = s.d[1][1], &z0 = s.d[0][2], &z1 = s.d[1][2];
  const V three = S::set1(3.0);
  const V3<S> c00 = cross(y0, z0), c11 = cross(y1, z1), a = cross(y1, z0), b = cross(y0, z1);
  const V3<S> sum = {a.x + b.x, a.y + b.y, a.z + b.z};
  f.c[0] = dot(x0, c00);
  f.c[1] = (dot(x1, c00) + dot(x0, sum)) / three;
  f.c[2] = (dot(x0, c11) + dot(x1, sum)) / three;
  f.c[3] = dot(x1, c11);
  const V3<S> p00 = cross_abs(y0, z0), p11 = cross_abs(y1, z1), pa = cross_abs(y1, z0), pb = cross_abs(y0, z1);
  const V3<S> psum = {pa.x + pb.x, pa.y + pb.y, pa.z + pb.z};
  const V p0 = dot_abs(x0, p00), p3 = dot_abs(x1, p11);
  const V p1 = (dot_abs(x1, p00) + dot_abs(x0, psum)) / three;
  const V p2 = (dot_abs(x0, p11) + dot_abs(x1, psum)) / three;
  const V perm = vmax<S>(vmax<S>(p0, p1), vmax<S>(p2, p3));
  f.e0 = S::set1(0x1p-49) * perm + S::set1(0x1p-900);
  V big = S::set1(0.0);
  for (int i = 0; i < 4; ++i) big = vmax<S>(big, S::abs(f.c[i]));
  f.step = S::set1(0x1p-49) * (big + f.e0) + S::set1(0x1p-900);
}

/// The two coordinates of a projection, lane by lane: i = axis + 1, j = axis + 2 (mod 3).
template <class S>
struct Axes {
  typename S::K axis1, axis0;
  TECIDO_BATCH_INLINE typename S::V i(const V3<S>& v) const { return S::select(axis1, v.z, S::select(axis0, v.y, v.x)); }
  TECIDO_BATCH_INLINE typename S::V j(const V3<S>& v) const { return S::select(axis1, v.x, S::select(axis0, v.z, v.y)); }
};

/// ccd_projected_quadratics: the axis along which (X0 + X1) x (Y0 + Y1) is largest (ties as
/// ccd breaks them), then den and the numerators in the other two coordinates.
template <class S, int K>
TECIDO_BATCH_INLINE void projected_quadratics(const Differences<S>& s, Bernstein<S, 3> (&q)[5]) {
  using V = typename S::V;
  using M = typename S::K;
  const V3<S>&X0 = s.d[0][0], &X1 = s.d[1][0], &Y0 = s.d[0][1], &Y1 = s.d[1][1];
  const V3<S> x = {X0.x + X1.x, X0.y + X1.y, X0.z + X1.z}, y = {Y0.x + Y1.x, Y0.y + Y1.y, Y0.z + Y1.z};
  const V n0 = S::abs(x.y * y.z - x.z * y.y), n1 = S::abs(x.z * y.x - x.x * y.z), n2 = S::abs(x.x * y.y - x.y * y.x);
  const M axis0 = S::lt(n2, n0);                            // axis = 2; n[0] > n[2]: 0
  const M axis1 = S::lt(S::select(axis0, n0, n2), n1);      // n[1] > n[axis]: 1
  const M is0 = S::kand(axis0, S::knot(axis1));
  // i = (axis + 1) % 3, j = (axis + 2) % 3: axis 2 -> (x, y), 0 -> (y, z), 1 -> (z, x).
  const Axes<S> ax{axis1, is0};
  constexpr int kUV[2][5][2] = {{{0, 1}, {2, 1}, {0, 2}, {3, 4}, {3, 4}}, {{0, 1}, {2, 1}, {0, 2}, {3, 1}, {0, 4}}};
  const V half = S::set1(0.5);
  for (int k = 0; k < 5; ++k) {
    const V3<S>&u0 = s.d[0][kUV[K][k][0]], &u1 = s.d[1][kUV[K][k][0]];
    const V3<S>&v0 = s.d[0][kUV[K][k][1]], &v1 = s.d[1][kUV[K][k][1]];
    const V u0i = ax.i(u0), u0j = ax.j(u0), u1i = ax.i(u1), u1j = ax.j(u1);
    const V v0i = ax.i(v0), v0j = ax.j(v0), v1i = ax.i(v1), v1j = ax.j(v1);
    Bernstein<S, 3>& b = q[k];
    b.c[0] = u0i * v0j - u0j * v0i;
    b.c[1] = ((u0i * v1j - u0j * v1i) + (u1i * v0j - u1j * v0i)) * half;
    b.c[2] = u1i * v1j - u1j * v1i;
    const V p0 = S::abs(u0i * v0j) + S::abs(u0j * v0i);
    const V p1 = (S::abs(u0i * v1j) + S::abs(u0j * v1i) + S::abs(u1i * v0j) + S::abs(u1j * v0i)) * half;
    const V p2 = S::abs(u1i * v1j) + S::abs(u1j * v1i);
    b.e0 = S::set1(0x1p-50) * vmax<S>(p0, vmax<S>(p1, p2)) + S::set1(0x1p-900);
    b.step = S::set1(0x1p-49) * (vmax<S>(S::abs(b.c[0]), vmax<S>(S::abs(b.c[1]), S::abs(b.c[2]))) + b.e0) +
             S::set1(0x1p-900);
  }
}

/// ccd_cubic_root(b, 2^-48), lane by lane: the lanes still iterating are masked, each lane
/// leaving the loop where the scalar code returns, with the value it returns.
template <class S>
TECIDO_BATCH_INLINE typename S::V cubic_root(const typename S::V (&b)[4]) {
  using V = typename S::V;
  using M = typename S::K;
  const V zero = S::set1(0.0), one = S::set1(1.0), two = S::set1(2.0), three = S::set1(3.0), tol = S::set1(0x1p-48);
  const V c0 = b[0], c1 = three * (b[1] - b[0]), c2 = three * (b[2] - two * b[1] + b[0]);
  const V c3 = b[3] - three * b[2] + three * b[1] - b[0];
  const M rising = S::lt(b[0], zero);
  V lo = zero, hi = one, s = b[0] / (b[0] - b[3]);
  s = S::select(S::kand(S::lt(zero, s), S::lt(s, one)), s, S::set1(0.5));
  V root = s;
  M active = S::all();
  for (int it = 0; it < 64 && S::bits(active); ++it) {
    const V p = ((c3 * s + c2) * s + c1) * s + c0;
    const V dp = (three * c3 * s + two * c2) * s + c1;
    const M exact = S::kand(active, S::kand(S::le(p, zero), S::le(zero, p)));  // p == 0: return s
    root = S::select(exact, s, root);
    active = S::kand(active, S::knot(exact));
    const M below = S::lt(p, zero);  // (p < 0) == rising: the root lies above s
    const M up = S::kor(S::kand(below, rising), S::kand(S::knot(below), S::knot(rising)));
    lo = S::select(S::kand(active, up), s, lo);
    hi = S::select(S::kand(active, S::knot(up)), s, hi);
    V next = s - p / dp;
    next = S::select(S::kand(S::lt(lo, next), S::lt(next, hi)), next, S::set1(0.5) * (lo + hi));
    const M done = S::kand(active, S::kor(S::le(S::abs(next - s), tol), S::le(hi - lo, tol)));
    root = S::select(done, next, root);
    active = S::kand(active, S::knot(done));
    s = S::select(active, next, s);
  }
  return S::select(active, s, root);  // lanes still iterating after 64 steps: ccd returns s
}

/// One de Casteljau step at s (ccd_lerp): (1 - s) x + s y.
template <class S>
TECIDO_BATCH_INLINE typename S::V lerp(typename S::V x, typename S::V y, typename S::V s) {
  return (S::set1(1.0) - s) * x + s * y;
}

/// The end coefficients of ccd_restrict_cubic(b, sa, sb): the cubic's values at sa and sb.
template <class S>
TECIDO_BATCH_INLINE void restricted_cubic_ends(const typename S::V (&b)[4], typename S::V sa, typename S::V sb,
                                               typename S::V& first, typename S::V& last) {
  using V = typename S::V;
  const V a1[3] = {lerp<S>(b[0], b[1], sa), lerp<S>(b[1], b[2], sa), lerp<S>(b[2], b[3], sa)};
  const V b1[3] = {lerp<S>(b[0], b[1], sb), lerp<S>(b[1], b[2], sb), lerp<S>(b[2], b[3], sb)};
  first = lerp<S>(lerp<S>(a1[0], a1[1], sa), lerp<S>(a1[1], a1[2], sa), sa);
  last = lerp<S>(lerp<S>(b1[0], b1[1], sb), lerp<S>(b1[1], b1[2], sb), sb);
}

/// ccd_restrict_quadratics for one quadratic.
template <class S>
TECIDO_BATCH_INLINE void restricted_quadratic(const typename S::V (&q)[3], typename S::V sa, typename S::V sb,
                                              typename S::V (&out)[3]) {
  using V = typename S::V;
  const V a0 = lerp<S>(q[0], q[1], sa), a1 = lerp<S>(q[1], q[2], sa);
  const V b0 = lerp<S>(q[0], q[1], sb), b1 = lerp<S>(q[1], q[2], sb);
  out[0] = lerp<S>(a0, a1, sa);
  out[1] = lerp<S>(a0, a1, sb);
  out[2] = lerp<S>(b0, b1, sb);
}

/// What the root visit knows before rule J (TimeSearch::Known at the root): den's certain
/// sign (sd: +1, -1, 0), its lower bound, and which numerators are certainly inside.
template <class S>
struct RootKnown {
  typename S::K dpos, dneg, inside[5], all_inside;
  typename S::V sd, den_low;
};

/// TimeSearch::jump at the root for the lanes of `lanes` where it is applicable: bits of
/// certified brackets, their ends in sa, sb (relative to [0, 1], which they equal).
template <class S>
TECIDO_BATCH_INLINE unsigned root_bracket(const Bernstein<S, 4>& f, unsigned lanes, typename S::V& s0,
                                          typename S::V& sa, typename S::V& sb) {
  using V = typename S::V;
  using M = typename S::K;
  const V zero = S::set1(0.0), one = S::set1(1.0), ef = f.e0;
  const M pos = S::lt(ef, f.c[0]), neg = S::lt(f.c[0], zero - ef);
  s0 = S::select(pos, one, S::select(neg, S::set1(-1.0), zero));
  const V minus_s0 = zero - s0;
  M applicable = S::kand(S::kor(pos, neg), S::lt(ef, minus_s0 * f.c[3]));
  for (int i = 0; i < 3; ++i) {
    const V d = f.c[i + 1] - f.c[i];
    applicable = S::kand(applicable, S::lt(S::set1(2.0) * ef + S::set1(0x1p-50) * S::abs(d) + S::set1(0x1p-1000), minus_s0 * d));
  }
  lanes &= S::bits(applicable);
  if (!lanes) return 0;
  const V tr = zero + cubic_root<S>(f.c) * one;  // lo + root * w on [0, 1]
  const V e1 = f.e0 + f.step;                    // the bound one level down
  M found = S::none();
  sa = sb = zero;
  for (double h = 0x1p-46; h <= 0.25 * 0x1p-20; h *= 16.0) {  // time tolerance 2^-20; 3h < 1 throughout
    const V vh = S::set1(h);
    const V a = vmax<S>(zero, S::floor(tr / vh) * vh - vh), b = vmin<S>(one, a + S::set1(3.0 * h));
    const V ra = (a - zero) / one, rb = (b - zero) / one;
    V first, last;
    restricted_cubic_ends<S>(f.c, ra, rb, first, last);
    const M ok = S::kand(S::kand(S::lt(e1, s0 * first), S::lt(e1, minus_s0 * last)), S::knot(found));
    sa = S::select(ok, ra, sa);
    sb = S::select(ok, rb, sb);
    found = S::kor(found, ok);
    if ((S::bits(found) & lanes) == lanes) break;
  }
  return lanes & S::bits(found);
}

/// Rule J's decision on the certified brackets of `lanes` whose numerators are not all inside:
/// the quadratics restricted to the bracket (TimeSearch::jump after its bracket): a numerator
/// certainly of den's opposite sign is a miss, every one within beta of inside a hit; den of
/// no certain sign, or neither, is left open.
template <class S, int kCount>
TECIDO_BATCH_INLINE void bracket_decision(const Bernstein<S, 3> (&q)[5], const RootKnown<S>& kn, typename S::V sa,
                                          typename S::V sb, unsigned lanes, unsigned& miss, unsigned& hit) {
  using V = typename S::V;
  using M = typename S::K;
  const V zero = S::set1(0.0), one = S::set1(1.0);
  V qr[3], e1 = q[0].e0 + q[0].step;  // bounds one level down
  restricted_quadratic<S>(q[0].c, sa, sb, qr);
  M pos, neg;
  certified_sign<S, 3>(qr, e1, pos, neg);
  // den's sign: known at the root, else certified on the bracket.
  const M known = S::kor(kn.dpos, kn.dneg), unknown = S::knot(known);
  const M dpos = S::kor(kn.dpos, S::kand(unknown, pos)), dneg = S::kor(kn.dneg, S::kand(unknown, neg));
  const V sd = S::select(known, kn.sd, S::select(pos, one, S::select(neg, S::set1(-1.0), zero)));
  lanes &= S::bits(S::kor(dpos, dneg));  // den without a certain sign: the inclusion search
  const V den_min = vmax<S>(S::select(known, kn.den_low, zero), vmin<S>(vmin<S>(sd * qr[0], sd * qr[1]), sd * qr[2]) - e1);
  M opposite = S::none(), inside = S::all();
  for (int k = 1; k < kCount; ++k) {
    e1 = q[k].e0 + q[k].step;
    restricted_quadratic<S>(q[k].c, sa, sb, qr);
    certified_sign<S, 3>(qr, e1, pos, neg);
    const M skip = kn.inside[k];  // inside over all of [0, 1]: not looked at again
    opposite = S::kor(opposite, S::kand(S::knot(skip), S::kor(S::kand(dpos, neg), S::kand(dneg, pos))));
    const V floor_k = e1 - S::set1(1e-9 / 27.72) * den_min;  // beta = distance_tolerance / 27.72
    const M near_inside = S::kand(S::kand(S::le(floor_k, sd * qr[0]), S::le(floor_k, sd * qr[1])), S::le(floor_k, sd * qr[2]));
    inside = S::kand(inside, S::kor(skip, near_inside));
  }
  miss |= lanes & S::bits(opposite);
  hit |= lanes & ~S::bits(opposite) & S::bits(inside);
}

/// The root decisions for the lanes of `lanes` (kind K: 0 vertex-face, 1 edge-edge): bits of
/// the lanes ccd answers miss, and hit, at its time search's root.
template <class S, int K>
TECIDO_BATCH_INLINE void root_decisions(const Points<S>& pts, unsigned lanes, unsigned& miss, unsigned& hit) {
  using V = typename S::V;
  using M = typename S::K;
  constexpr int kCount = K == 0 ? 4 : 5;  // den and the numerators
  const V zero = S::set1(0.0), one = S::set1(1.0);
  Differences<S> s;
  differences<S, K>(pts, s);
  Bernstein<S, 4> f;
  cubic_with_permanent<S>(s, f);
  M pos, neg;
  certified_sign<S, 4>(f.c, f.e0, pos, neg);
  miss = lanes & S::bits(S::kor(pos, neg));  // rule 1
  hit = 0;
  lanes &= ~miss;
  if (!lanes) return;
  Bernstein<S, 3> q[5];
  projected_quadratics<S, K>(s, q);
  RootKnown<S> kn;
  certified_sign<S, 3>(q[0].c, q[0].e0, kn.dpos, kn.dneg);
  kn.sd = S::select(kn.dpos, one, S::select(kn.dneg, S::set1(-1.0), zero));
  kn.den_low = vmin<S>(vmin<S>(kn.sd * q[0].c[0], kn.sd * q[0].c[1]), kn.sd * q[0].c[2]) - q[0].e0;
  M opposite = S::none();
  kn.all_inside = S::kor(kn.dpos, kn.dneg);
  for (int k = 1; k < kCount; ++k) {
    certified_sign<S, 3>(q[k].c, q[k].e0, pos, neg);
    opposite = S::kor(opposite, S::kor(S::kand(kn.dpos, neg), S::kand(kn.dneg, pos)));
    kn.inside[k] = S::kor(S::kand(kn.dpos, pos), S::kand(kn.dneg, neg));
    kn.all_inside = S::kand(kn.all_inside, kn.inside[k]);
  }
  const unsigned rule2 = lanes & S::bits(opposite);
  miss |= rule2;
  lanes &= ~rule2;
  V s0 = zero, sa = zero, sb = zero;
  const unsigned bracketed = lanes ? root_bracket<S>(f, lanes, s0, sa, sb) : 0u;
  const unsigned refined = S::bits(kn.all_inside);
  hit |= bracketed & refined;  // every numerator inside: refine()'s jump, a hit at the bracket
  if (bracketed & ~refined) bracket_decision<S, kCount>(q, kn, sa, sb, bracketed & ~refined, miss, hit);
}
