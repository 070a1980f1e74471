/// The box tree's lane masks (triangle_bvh.cpp) written once over the single-precision lane
/// type F of core's SIMD layer (core/simd/float_lanes.h): the 4 x 4 masks of a node pair (bit
/// 4k + l: lane k of node a with lane l of node b) in F::kPasses passes of F::kWidth lanes,
/// 4 passes with SSE2, one with AVX-512F. The same compares and operations lane by lane
/// whatever the width, so the masks, hence the tree's output, do not depend on it.
// A per-width file (core/simd/target.h): triangle_bvh.cpp has core/simd/for_each_width.inl
// include it once per width. No include guard, no includes, no namespace. The three 16-bit
// masks are entry points called from baseline code, so plain inline: a wide copy cannot be
// forced inline into a caller without its instruction set.

/// The lanes of one pass as bits of the 16-bit mask.
template <class F>
TECIDO_SIMD_INLINE unsigned pass_bits(typename F::K k, int pass) {
  return F::bits(k) << (F::kWidth * pass);
}

/// Bit 4k + l set when lane k of node a's boxes overlaps lane l of node b's (closed intervals,
/// exact compares). lo and hi point at a node's lo[3][4] / hi[3][4] rows.
template <class F>
inline unsigned box_mask16(const float* alo, const float* ahi, const float* blo, const float* bhi) {
  unsigned out = 0;
  for (int pass = 0; pass < F::kPasses; ++pass) {
    typename F::K m = F::all();
    for (int d = 0; d < 3; ++d) {
      m = F::kand(m, F::le(F::pair_b(blo + 4 * d, pass), F::pair_a(ahi + 4 * d, pass)));
      m = F::kand(m, F::le(F::pair_a(alo + 4 * d, pass), F::pair_b(bhi + 4 * d, pass)));
    }
    out |= pass_bits<F>(m, pass);
  }
  return out;
}

/// Bit 4k + l set when the triangles of lane k of leaf a and lane l of leaf b share a vertex:
/// av and bv point at the leaves' v[3][4] vertex-id rows (nine equality tests per lane).
template <class F>
TECIDO_SIMD_INLINE unsigned share_mask16(const int* av, const int* bv) {
  unsigned out = 0;
  for (int pass = 0; pass < F::kPasses; ++pass) {
    const typename F::I b0 = F::pair_bi(bv, pass), b1 = F::pair_bi(bv + 4, pass), b2 = F::pair_bi(bv + 8, pass);
    typename F::K share = F::none();
    for (int d = 0; d < 3; ++d) {
      const typename F::I a = F::pair_ai(av + 4 * d, pass);
      share = F::kor(share, F::kor(F::eqi(a, b0), F::kor(F::eqi(a, b1), F::eqi(a, b2))));
    }
    out |= pass_bits<F>(share, pass);
  }
  return out;
}

/// box_mask16 less the pairs that share a vertex: the triangle pairs of two leaves to test.
template <class F>
inline unsigned leaf_mask16(const float* alo, const float* ahi, const float* blo, const float* bhi,
                                        const int* av, const int* bv) {
  return box_mask16<F>(alo, ahi, blo, bhi) & ~share_mask16<F>(av, bv) & 0xFFFFu;
}

/// Bit 4k + l set when the kinetic boxes of lane k of a and lane l of b may meet
/// (TriangleBvh::kinetic_lanes gives the method). alo .. bhi point at Frames lo / hi
/// ([frame][axis][lane]).
template <class F>
inline unsigned kinetic_mask16(const float* alo, const float* ahi, const float* blo, const float* bhi) {
  using V = typename F::V;
  using K = typename F::K;
  unsigned out = 0;
  for (int pass = 0; pass < F::kPasses; ++pass) {
    const V zero = F::set1(0.0f);
    V lower = zero, upper = F::set1(1.0f);
    K reject = F::none();
    for (int c = 0; c < 3; ++c) {
      for (int k = 0; k < 2; ++k) {
        // Constraint k of axis c at frame f: hi_b - lo_a (k = 0) or hi_a - lo_b (k = 1).
        V v[2];
        for (int f = 0; f < 2; ++f) {
          const int row = 12 * f + 4 * c;
          v[f] = k == 0 ? F::pair_b(bhi + row, pass) - F::pair_a(alo + row, pass)
                        : F::pair_a(ahi + row, pass) - F::pair_b(blo + row, pass);
        }
        const V m = F::max(F::abs(v[0]), F::abs(v[1])) * F::set1(0x1p-21f) + F::set1(FLT_MIN);
        const V a = v[0] + m, e = v[1] + m;
        const K rising = F::lt(a, zero), e_neg = F::lt(e, zero);
        reject = F::kor(reject, F::kand(rising, e_neg));
        const K falling = F::kandnot(rising, e_neg);
        const V t = a / (a - e);
        const V lo = t * F::set1(1.0f - 0x1p-20f) - F::set1(0x1p-100f);
        const V hi = t * F::set1(1.0f + 0x1p-20f) + F::set1(0x1p-100f);
        lower = F::select(rising, F::max(lower, lo), lower);
        upper = F::select(falling, F::min(upper, hi), upper);
      }
    }
    const K disjoint = F::kor(reject, F::lt(upper, lower));
    out |= pass_bits<F>(F::kandnot(disjoint, F::all()), pass);
  }
  return out;
}

/// Bit k set when lane k of a node (lo and hi at its lo[3][4] / hi[3][4] rows) overlaps the
/// box (lo, hi): F::kWidth lanes at a time (widths 1 and 4).
template <class F>
TECIDO_SIMD_INLINE unsigned lanes_overlapping(const float* blo, const float* bhi, const float* lo, const float* hi) {
  unsigned out = 0;
  for (int first = 0; first < 4; first += F::kWidth) {
    typename F::K m = F::all();
    for (int d = 0; d < 3; ++d) {
      m = F::kand(m, F::le(F::load(blo + 4 * d + first), F::set1(hi[d])));
      m = F::kand(m, F::le(F::set1(lo[d]), F::load(bhi + 4 * d + first)));
    }
    out |= F::bits(m) << first;
  }
  return out;
}

/// Bit k set when triangle (v0, v1, v2) shares a vertex with lane k's triangle of a leaf (bv
/// at its v[3][4] rows), F::kWidth lanes at a time (widths 1 and 4).
template <class F>
TECIDO_SIMD_INLINE unsigned lanes_sharing(const int* bv, int v0, int v1, int v2) {
  unsigned out = 0;
  for (int first = 0; first < 4; first += F::kWidth) {
    const typename F::I l0 = F::loadi(bv + first), l1 = F::loadi(bv + 4 + first), l2 = F::loadi(bv + 8 + first);
    typename F::K s = F::none();
    for (int v : {v0, v1, v2}) {
      const typename F::I q = F::set1i(v);
      s = F::kor(s, F::kor(F::eqi(q, l0), F::kor(F::eqi(q, l1), F::eqi(q, l2))));
    }
    out |= F::bits(s) << first;
  }
  return out;
}
