/// The kinetic box test of core's continuous collision test (kinetic_boxes.h) over the lane type
/// S of core's SIMD layer (core/simd/), for the batched first stages (batch/kernels.inl, widths
/// 1, 2, 4, 8): kinetic_boxes.cpp's operations in its order, its early returns turned into lane
/// masks (they select, they never change a value computed), so every width decides as the
/// scalar code. The scalar test keeps its branchy form for speed (kinetic_boxes.cpp says why).
// A per-width file (core/simd/target.h), included after core/simd/lane_math.inl. No include
// guard, no includes, no namespace.

/// Boxes of two primitives at both frames: lo[frame][coordinate], hi likewise, per lane.
template <class S>
struct PairBoxes {
  typename S::V alo[2][3], ahi[2][3], blo[2][3], bhi[2][3];
};

/// The boxes overlap at t = 0 or at t = 1 (exact compares): then the kinetic test
/// answers "not disjoint".
template <class S>
TECIDO_SIMD_INLINE typename S::K overlap_at_a_frame(const PairBoxes<S>& b) {
  typename S::K ov[2];
  for (int t = 0; t < 2; ++t) {
    ov[t] = S::all();
    for (int c = 0; c < 3; ++c)
      ov[t] = S::kand(ov[t], S::kand(S::le(b.alo[t][c], b.bhi[t][c]), S::le(b.blo[t][c], b.ahi[t][c])));
  }
  return S::kor(ov[0], ov[1]);
}

/// The linear program of the kinetic boxes (after the overlap at a frame): the lanes where no
/// time in [0, 1] satisfies the six widened constraints (kinetic_boxes.h gives the method).
template <class S>
TECIDO_SIMD_INLINE typename S::K kinetic_program_infeasible(const PairBoxes<S>& b) {
  using V = typename S::V;
  using K = typename S::K;
  const V zero = S::set1(0.0);
  K both_negative = S::none(), at0 = S::all(), at1 = S::all();
  V lower = zero, upper = S::set1(1.0);
  for (int c = 0; c < 3; ++c) {
    const V v0[2] = {b.bhi[0][c] - b.alo[0][c], b.ahi[0][c] - b.blo[0][c]};
    const V v1[2] = {b.bhi[1][c] - b.alo[1][c], b.ahi[1][c] - b.blo[1][c]};
    for (int k = 0; k < 2; ++k) {
      const V m = S::set1(0x1p-50) * vmax<S>(S::abs(v0[k]), S::abs(v1[k]));
      const V a = v0[k] + m, e = v1[k] + m;
      const K a_neg = S::lt(a, zero), e_neg = S::lt(e, zero);
      both_negative = S::kor(both_negative, S::kand(a_neg, e_neg));
      at0 = S::kand(at0, S::le(zero, a));
      at1 = S::kand(at1, S::le(zero, e));
      const K falling = S::kand(S::knot(a_neg), e_neg);
      lower = S::select(a_neg, vmax<S>(lower, ((zero - a) / (e - a)) * S::set1(1.0 - 0x1p-50)), lower);
      upper = S::select(falling, vmin<S>(upper, (a / (a - e)) * S::set1(1.0 + 0x1p-50)), upper);
    }
  }
  return S::kor(both_negative, S::kand(S::knot(S::kor(at0, at1)), S::lt(upper, lower)));
}

