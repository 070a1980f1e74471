/// The static filter of the plane-side test of tri_tri_intersect (tri_tri_intersect.cpp,
/// plane_sides) written once over the lane type S of core's SIMD layer (core/simd/): the
/// scalar test runs it at width 1, the batched rejection of eight pairs (tri_tri_reject8) at
/// the widest width the CPU has, the same operations in the same order lane by lane.
// A per-width file (core/simd/target.h): tri_tri_intersect.cpp has core/simd/for_each_width.inl
// include it once per width, after kCoefPad and kErrBound. No include guard, no includes, no
// namespace.

/// A triangle's plane as the filter needs it: its first corner t0, the edges u = t1 - t0 and
/// v = t2 - t0, the normal n = u x v and the permanent's coefficients p (|products|, padded).
template <class S>
struct PlaneFilter {
  V3<S> t0, u, v, n, p;
};

template <class S>
TECIDO_SIMD_INLINE PlaneFilter<S> plane_filter(const V3<S>& t0, const V3<S>& t1, const V3<S>& t2) {
  using V = typename S::V;
  PlaneFilter<S> f;
  f.t0 = t0;
  f.u = {t1.x - t0.x, t1.y - t0.y, t1.z - t0.z};
  f.v = {t2.x - t0.x, t2.y - t0.y, t2.z - t0.z};
  const V3<S>&u = f.u, &v = f.v;
  const V uyvz = u.y * v.z, uzvy = u.z * v.y, uzvx = u.z * v.x;
  const V uxvz = u.x * v.z, uxvy = u.x * v.y, uyvx = u.y * v.x;
  f.n = {uyvz - uzvy, uzvx - uxvz, uxvy - uyvx};
  const V pad = S::set1(kCoefPad);
  f.p = {S::abs(uyvz) + S::abs(uzvy) + pad, S::abs(uzvx) + S::abs(uxvz) + pad, S::abs(uxvy) + S::abs(uyvx) + pad};
  return f;
}

/// [t0, t1, t2, x] up to sign, det = (x - t0) . n, and its static error bound: its sign is
/// certain where |det| > errbound.
template <class S>
TECIDO_SIMD_INLINE void side_filter(const PlaneFilter<S>& f, const V3<S>& x, typename S::V& det,
                                    typename S::V& errbound) {
  using V = typename S::V;
  const V wx = x.x - f.t0.x, wy = x.y - f.t0.y, wz = x.z - f.t0.z;
  det = wx * f.n.x + wy * f.n.y + wz * f.n.z;
  const V awx = S::abs(wx), awy = S::abs(wy), awz = S::abs(wz);
  const V permanent = awx * f.p.x + awy * f.p.y + awz * f.p.z;
  errbound = S::set1(kErrBound) * permanent + S::set1(detail::kUnderflowPad);
}

/// The points at offsets idx[first ..] (3 * vertex) of x, one per lane.
template <class S>
TECIDO_SIMD_INLINE V3<S> gather_points(const double* x, const int* idx) {
  return {S::gather(x, idx), S::gather(x + 1, idx), S::gather(x + 2, idx)};
}

/// tri_tri_reject8's lanes first .. first + S::kWidth: bit l set when the three corners of
/// p are certainly strictly on one side of q's plane.
template <class S>
TECIDO_SIMD_INLINE unsigned reject_lanes(const double* x, const int (&pv)[3][8], const int (&qv)[3][8], int first) {
  const PlaneFilter<S> f = plane_filter<S>(gather_points<S>(x, qv[0] + first), gather_points<S>(x, qv[1] + first),
                                           gather_points<S>(x, qv[2] + first));
  typename S::K pos = S::all(), neg = S::all();
  for (int i = 0; i < 3; ++i) {
    typename S::V det, errbound;
    side_filter<S>(f, gather_points<S>(x, pv[i] + first), det, errbound);
    pos = S::kand(pos, S::lt(errbound, det));
    neg = S::kand(neg, S::lt(errbound, S::set1(0.0) - det));
  }
  return S::bits(S::kor(pos, neg));
}

/// tri_tri_reject8 at width S::kWidth (8 / width passes).
template <class S>
unsigned reject8(const double* x, const int (&pv)[3][8], const int (&qv)[3][8]) {
  unsigned m = 0;
  for (int first = 0; first < 8; first += S::kWidth) m |= reject_lanes<S>(x, pv, qv, first) << first;
  return m;
}
