/// The arithmetic of core's continuous collision time search (time_search.h) written once over
/// the lane type S of core's SIMD layer (core/simd/): the coplanarity cubic and its bounds, the
/// projected quadratics and theirs, certified signs, the safeguarded Newton iteration, the
/// restrictions to a bracket, rule J's bracket and its decision. The scalar test instantiates
/// them at width 1 (decisions.h: coplanarity_cubic.cpp, projected_quadratics.cpp,
/// cubic_root.cpp, time_search.cpp); the batched first stages at widths 2, 4 and 8
/// (batch/stages.cpp). Every lane runs the scalar code's operations in its order, so the
/// decisions are bit for bit the same whatever the width.
///
/// Masks replace branches: a lane's value is selected, never computed differently. std::min
/// and std::max are vmin and vmax (the same choice); C++'s < and <= are S::lt and S::le (false
/// on NaN); an int sign s is the double s (+1, -1, 0), whose products are exact.
// A per-width file (core/simd/target.h): included inside each width's namespace and target
// region after core/simd/lane_math.inl. No include guard, no includes, no namespace.

/// The Bernstein coefficients f[0..3] of the coplanarity cubic det(X, Y, Z) on [0, 1]
/// (coplanarity_cubic.h) from X, Y, Z at t = 0 and t = 1.
template <class S>
TECIDO_SIMD_INLINE void cubic_coefficients(const V3<S>& x0, const V3<S>& x1, const V3<S>& y0, const V3<S>& y1,
                                           const V3<S>& z0, const V3<S>& z1, typename S::V* f) {
  const typename S::V three = S::set1(3.0);
  const V3<S> c00 = cross<S>(y0, z0), c11 = cross<S>(y1, z1);
  const V3<S> sum = add<S>(cross<S>(y1, z0), cross<S>(y0, z1));
  f[0] = dot<S>(x0, c00);
  f[1] = (dot<S>(x1, c00) + dot<S>(x0, sum)) / three;
  f[2] = (dot<S>(x0, c11) + dot<S>(x1, sum)) / three;
  f[3] = dot<S>(x1, c11);
}

/// The cubic's cheap error bound from the largest components mx, my, mz of X, Y, Z over both
/// times: 6 mx my mz bounds every coefficient's permanent.
template <class S>
TECIDO_SIMD_INLINE typename S::V cubic_cheap_bound(typename S::V mx, typename S::V my, typename S::V mz) {
  return S::set1(0x1p-49 * (6.0 * (1.0 + 0x1p-50))) * (mx * my * mz) + S::set1(0x1p-900);
}

/// The cubic's error bound from the coefficients' permanents (the bound of last resort).
template <class S>
TECIDO_SIMD_INLINE typename S::V cubic_permanent_bound(const V3<S>& x0, const V3<S>& x1, const V3<S>& y0,
                                                       const V3<S>& y1, const V3<S>& z0, const V3<S>& z1) {
  using V = typename S::V;
  const V three = S::set1(3.0);
  const V3<S> p00 = cross_abs<S>(y0, z0), p11 = cross_abs<S>(y1, z1);
  const V3<S> psum = add<S>(cross_abs<S>(y1, z0), cross_abs<S>(y0, z1));
  const V p0 = dot_abs<S>(x0, p00), p3 = dot_abs<S>(x1, p11);
  const V p1 = (dot_abs<S>(x1, p00) + dot_abs<S>(x0, psum)) / three;
  const V p2 = (dot_abs<S>(x0, p11) + dot_abs<S>(x1, psum)) / three;
  const V perm = vmax<S>(vmax<S>(p0, p1), vmax<S>(p2, p3));
  return S::set1(0x1p-49) * perm + S::set1(0x1p-900);
}

/// The largest |c[i]| of n coefficients (0 for none).
template <class S>
TECIDO_SIMD_INLINE typename S::V largest_abs(const typename S::V* c, int n) {
  typename S::V big = S::set1(0.0);
  for (int i = 0; i < n; ++i) big = vmax<S>(big, S::abs(c[i]));
  return big;
}

/// CcdErrorBound::set_step (bernstein.h): the bound's growth per halving.
template <class S>
TECIDO_SIMD_INLINE typename S::V bound_step(typename S::V max_abs_coefficient, typename S::V e0) {
  return S::set1(0x1p-49) * (max_abs_coefficient + e0) + S::set1(0x1p-900);
}

/// The lanes where every one of the n coefficients exceeds e (pos) or is below -e (neg):
/// ccd_certified_sign's +1 and -1.
template <class S>
TECIDO_SIMD_INLINE void certified_sign(const typename S::V* c, int n, typename S::V e, typename S::K& pos,
                                       typename S::K& neg) {
  typename S::V lo = c[0], hi = c[0];
  for (int i = 1; i < n; ++i) {
    lo = S::select(S::lt(c[i], lo), c[i], lo);
    hi = S::select(S::lt(hi, c[i]), c[i], hi);
  }
  pos = S::lt(e, lo);
  neg = S::lt(hi, S::set1(0.0) - e);
}

/// A sign as a number: +1 where pos, -1 where neg, 0 elsewhere.
template <class S>
TECIDO_SIMD_INLINE typename S::V sign_value(typename S::K pos, typename S::K neg) {
  return S::select(pos, S::set1(1.0), S::select(neg, S::set1(-1.0), S::set1(0.0)));
}

/// The projection of projected_quadratics.h, lane by lane: the axis along which
/// (X0 + X1) x (Y0 + Y1) is largest (ties broken toward 2, then 0), and its two other
/// coordinates i = axis + 1, j = axis + 2 (mod 3).
template <class S>
struct Projection {
  typename S::K axis1, axis0;  ///< axis 1; axis 0 (else axis 2)
  TECIDO_SIMD_INLINE typename S::V i(const V3<S>& v) const { return S::select(axis1, v.z, S::select(axis0, v.y, v.x)); }
  TECIDO_SIMD_INLINE typename S::V j(const V3<S>& v) const { return S::select(axis1, v.x, S::select(axis0, v.z, v.y)); }
};
template <class S>
TECIDO_SIMD_INLINE Projection<S> projection(const V3<S>& x0, const V3<S>& x1, const V3<S>& y0, const V3<S>& y1) {
  using V = typename S::V;
  const V3<S> x = add<S>(x0, x1), y = add<S>(y0, y1);
  const V n0 = S::abs(x.y * y.z - x.z * y.y), n1 = S::abs(x.z * y.x - x.x * y.z), n2 = S::abs(x.x * y.y - x.y * y.x);
  const typename S::K axis0 = S::lt(n2, n0);                   // axis = 2; n[0] > n[2]: 0
  const typename S::K axis1 = S::lt(S::select(axis0, n0, n2), n1);  // n[1] > n[axis]: 1
  return {axis1, S::kand(axis0, S::knot(axis1))};
}

/// One projected quadratic det2(U, V) in Bernstein form on [0, 1] (c[0..2]) with its error
/// bound e0 and step (projected_quadratics.h).
template <class S>
TECIDO_SIMD_INLINE void projected_quadratic(const Projection<S>& pr, const V3<S>& u0, const V3<S>& u1, const V3<S>& v0,
                                            const V3<S>& v1, typename S::V* c, typename S::V& e0, typename S::V& step) {
  using V = typename S::V;
  const V half = S::set1(0.5);
  const V u0i = pr.i(u0), u0j = pr.j(u0), u1i = pr.i(u1), u1j = pr.j(u1);
  const V v0i = pr.i(v0), v0j = pr.j(v0), v1i = pr.i(v1), v1j = pr.j(v1);
  c[0] = u0i * v0j - u0j * v0i;
  c[1] = ((u0i * v1j - u0j * v1i) + (u1i * v0j - u1j * v0i)) * half;
  c[2] = u1i * v1j - u1j * v1i;
  const V p0 = S::abs(u0i * v0j) + S::abs(u0j * v0i);
  const V p1 = (S::abs(u0i * v1j) + S::abs(u0j * v1i) + S::abs(u1i * v0j) + S::abs(u1j * v0i)) * half;
  const V p2 = S::abs(u1i * v1j) + S::abs(u1j * v1i);
  e0 = S::set1(0x1p-50) * vmax<S>(p0, vmax<S>(p1, p2)) + S::set1(0x1p-900);
  step = bound_step<S>(vmax<S>(S::abs(c[0]), vmax<S>(S::abs(c[1]), S::abs(c[2]))), e0);
}

/// ccd_cubic_root (cubic_root.h): a root of the Bernstein cubic b on [0, 1], lane by lane; the
/// lanes still iterating are masked, each leaving the loop where the scalar iteration returns,
/// with the value it returns.
template <class S>
TECIDO_SIMD_INLINE typename S::V cubic_root(const typename S::V* b, typename S::V tol) {
  using V = typename S::V;
  using M = typename S::K;
  const V zero = S::set1(0.0), one = S::set1(1.0), two = S::set1(2.0), three = S::set1(3.0);
  // Power basis (Horner is cheaper than de Casteljau; the result is only an approximation).
  const V c0 = b[0], c1 = three * (b[1] - b[0]), c2 = three * (b[2] - two * b[1] + b[0]);
  const V c3 = b[3] - three * b[2] + three * b[1] - b[0];
  const M rising = S::lt(b[0], zero);  // p < 0 left of the root
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
    const M newton = S::kand(S::lt(lo, next), S::lt(next, hi));
    next = S::select(newton, next, S::set1(0.5) * (lo + hi));
    // After a Newton step d = next - s, next is off the root by about |p''| d^2 / (2 |p'|):
    // done when that is below tol / 2, which saves the last step (whose size only confirms
    // it). Only a speed matter: the caller certifies whatever comes back.
    const V d = next - s, curvature = S::abs(S::set1(6.0) * c3 * s + two * c2);
    const M predicted = S::kand(newton, S::le(d * d * curvature, tol * S::abs(dp)));
    const M done = S::kand(active, S::kor(S::kor(S::le(S::abs(d), tol), S::le(hi - lo, tol)), predicted));
    root = S::select(done, next, root);
    active = S::kand(active, S::knot(done));
    s = S::select(active, next, s);
  }
  return S::select(active, s, root);  // lanes still iterating after 64 steps: s
}

/// One de Casteljau step at s (ccd_lerp): (1 - s) x + s y.
template <class S>
TECIDO_SIMD_INLINE typename S::V lerp(typename S::V x, typename S::V y, typename S::V s) {
  return (S::set1(1.0) - s) * x + s * y;
}

/// The end coefficients of ccd_restrict_cubic(b, sa, sb): the cubic's values at sa and sb.
template <class S>
TECIDO_SIMD_INLINE void restricted_cubic_ends(const typename S::V* b, typename S::V sa, typename S::V sb,
                                              typename S::V& first, typename S::V& last) {
  using V = typename S::V;
  const V a1[3] = {lerp<S>(b[0], b[1], sa), lerp<S>(b[1], b[2], sa), lerp<S>(b[2], b[3], sa)};
  const V b1[3] = {lerp<S>(b[0], b[1], sb), lerp<S>(b[1], b[2], sb), lerp<S>(b[2], b[3], sb)};
  first = lerp<S>(lerp<S>(a1[0], a1[1], sa), lerp<S>(a1[1], a1[2], sa), sa);
  last = lerp<S>(lerp<S>(b1[0], b1[1], sb), lerp<S>(b1[1], b1[2], sb), sb);
}

/// ccd_restrict_quadratics for one quadratic q[0..2]: its coefficients on [sa, sb].
template <class S>
TECIDO_SIMD_INLINE void restricted_quadratic(const typename S::V* q, typename S::V sa, typename S::V sb,
                                             typename S::V* out) {
  using V = typename S::V;
  const V a0 = lerp<S>(q[0], q[1], sa), a1 = lerp<S>(q[1], q[2], sa);
  const V b0 = lerp<S>(q[0], q[1], sb), b1 = lerp<S>(q[1], q[2], sb);
  out[0] = lerp<S>(a0, a1, sa);
  out[1] = lerp<S>(a0, a1, sb);
  out[2] = lerp<S>(b0, b1, sb);
}

/// Rule J's precondition (time_search.h): the lanes where the cubic f certainly changes sign
/// and is certainly monotone under the bound ef; s0 is f's sign at the start (+1, -1; 0 where
/// it has none).
template <class S>
TECIDO_SIMD_INLINE typename S::K monotone_crossing(const typename S::V* f, typename S::V ef, typename S::V& s0) {
  using V = typename S::V;
  const V zero = S::set1(0.0);
  const typename S::K pos = S::lt(ef, f[0]), neg = S::lt(f[0], zero - ef);
  s0 = sign_value<S>(pos, neg);
  const V minus_s0 = zero - s0;
  typename S::K ok = S::kand(S::kor(pos, neg), S::lt(ef, minus_s0 * f[3]));
  for (int i = 0; i < 3; ++i) {
    const V d = f[i + 1] - f[i];
    ok = S::kand(ok, S::lt(S::set1(2.0) * ef + S::set1(0x1p-50) * S::abs(d) + S::set1(0x1p-1000), minus_s0 * d));
  }
  return ok;
}

/// A certified bracket of the cubic's root (rule J): on the interval [lo, hi] of width w (a
/// power of two), the
/// root's approximation tr, brackets [a, b] of width 3h for h = 2^-46, 2^-42, ... up to h_max
/// (while 3h < w), until the cubic restricted to one (sa, sb relative to the interval) has
/// certainly opposite signs at its ends under e1, the bound one level down. Returns the lanes
/// with a certified bracket; stops as soon as every lane of `lanes` has one.
template <class S>
TECIDO_SIMD_INLINE typename S::K certify_bracket(const typename S::V* f, typename S::V tr, typename S::V lo,
                                                 typename S::V hi, double w, typename S::V e1, typename S::V s0,
                                                 double h_max, unsigned lanes, typename S::V& a, typename S::V& b,
                                                 typename S::V& sa, typename S::V& sb) {
  using V = typename S::V;
  // w is a power of two (the time search's intervals halve [0, 1]), and so is h: dividing by
  // either is multiplying by its reciprocal, exactly, without a division's latency.
  const V inv_w = S::set1(1.0 / w), minus_s0 = S::set1(0.0) - s0;
  typename S::K found = S::none();
  a = b = sa = sb = S::set1(0.0);
  for (double h = 0x1p-46; h <= h_max && 3.0 * h < w; h *= 16.0) {
    const V vh = S::set1(h);
    const V ca = vmax<S>(lo, S::floor(tr * S::set1(1.0 / h)) * vh - vh), cb = vmin<S>(hi, ca + S::set1(3.0 * h));
    const V ra = (ca - lo) * inv_w, rb = (cb - lo) * inv_w;
    V first, last;
    restricted_cubic_ends<S>(f, ra, rb, first, last);
    const typename S::K ok = S::kand(S::kand(S::lt(e1, s0 * first), S::lt(e1, minus_s0 * last)), S::knot(found));
    a = S::select(ok, ca, a);
    b = S::select(ok, cb, b);
    sa = S::select(ok, ra, sa);
    sb = S::select(ok, rb, sb);
    found = S::kor(found, ok);
    if ((S::bits(found) & lanes) == lanes) break;
  }
  return found;
}

/// What an interval knows of den before rule J's bracket (TimeSearch::Known): its certain sign
/// (dpos, dneg; sd its value), a lower bound of sd * den, and the numerators certainly inside.
template <class S>
struct DenKnown {
  typename S::K dpos, dneg;
  typename S::V sd, den_low;
  typename S::K inside[5];  ///< [0] unused (den)
};

/// Rule J's decision on a certified bracket [sa, sb] from the quadratics q[k][0..2] (den
/// first, `count` of them) restricted to it, e1[k] their bounds one level down: a numerator
/// certainly of den's opposite sign is a miss (rule 2 at the only coplanar instant); every
/// numerator at least e1 - beta den_min in sd's direction is a hit (rule 3a there). Lanes of
/// neither, or where den has no certain sign, go to the inclusion search (`open`).
template <class S>
TECIDO_SIMD_INLINE void bracket_decision(const typename S::V (*q)[3], const typename S::V* e1, int count,
                                         const DenKnown<S>& kn, typename S::V sa, typename S::V sb, double beta,
                                         typename S::K& miss, typename S::K& hit, typename S::K& open) {
  using V = typename S::V;
  using M = typename S::K;
  V qr[3];
  restricted_quadratic<S>(q[0], sa, sb, qr);
  M pos, neg;
  certified_sign<S>(qr, 3, e1[0], pos, neg);
  // den's sign: known before, else certified on the bracket.
  const M known = S::kor(kn.dpos, kn.dneg), unknown = S::knot(known);
  const M dpos = S::kor(kn.dpos, S::kand(unknown, pos)), dneg = S::kor(kn.dneg, S::kand(unknown, neg));
  const V sd = S::select(known, kn.sd, sign_value<S>(pos, neg));
  const M signed_den = S::kor(dpos, dneg);
  const V den_min =
      vmax<S>(S::select(known, kn.den_low, S::set1(0.0)), vmin<S>(vmin<S>(sd * qr[0], sd * qr[1]), sd * qr[2]) - e1[0]);
  M opposite = S::none(), inside = S::all();
  for (int k = 1; k < count; ++k) {
    restricted_quadratic<S>(q[k], sa, sb, qr);
    certified_sign<S>(qr, 3, e1[k], pos, neg);
    const M skip = kn.inside[k];  // inside over the whole interval: not looked at again
    opposite = S::kor(opposite, S::kand(S::knot(skip), S::kor(S::kand(dpos, neg), S::kand(dneg, pos))));
    const V floor_k = e1[k] - S::set1(beta) * den_min;
    const M near = S::kand(S::kand(S::le(floor_k, sd * qr[0]), S::le(floor_k, sd * qr[1])), S::le(floor_k, sd * qr[2]));
    inside = S::kand(inside, S::kor(skip, near));
  }
  miss = S::kand(signed_den, opposite);
  hit = S::kand(signed_den, S::kand(S::knot(opposite), inside));
  open = S::kand(S::knot(miss), S::knot(hit));
}
