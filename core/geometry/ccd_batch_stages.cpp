#include "core/geometry/ccd_batch_stages.h"

#include <algorithm>
#include <cstddef>
#include <cstring>

// The kernels are written once against a small set of lane operations (a "Simd" traits class:
// loads, arithmetic, ordered comparisons giving masks, selection) and compiled three times:
// baseline (2 lanes, SSE2, through GCC vector types), AVX (4 lanes, GCC vector types) and
// AVX-512F (8 lanes, intrinsics: GCC 12 expands vector-type comparisons lane by lane there, as
// AVX-512F keeps comparison results in mask registers). Every lane runs the scalar code's
// operations in its order; fp-contract is off in the wide functions so that no multiply-add
// is fused (AVX-512F has FMA; the baseline and AVX have none to fuse into).
#if defined(__GNUC__) && defined(__x86_64__)
#define TECIDO_BATCH_X86 1
#include <immintrin.h>
#define TECIDO_BATCH_TARGET_AVX __attribute__((target("avx"), optimize("fp-contract=off"), flatten))
#define TECIDO_BATCH_TARGET_AVX512 __attribute__((target("avx512f"), optimize("fp-contract=off"), flatten))
#else
#define TECIDO_BATCH_X86 0
#endif
#define TECIDO_BATCH_INLINE inline __attribute__((always_inline))

// The helpers below pass wide vectors by value; they are internal and always inlined into the
// kernel of their width, so no call ever crosses an ABI boundary: GCC's note that such a
// signature's ABI differs without AVX does not apply.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace tecido {

namespace {

/// GCC vector types of W doubles and of W 64-bit integers (comparison results: -1 true, 0 false).
template <int W>
struct VecTypes {
  typedef double V __attribute__((vector_size(8 * W)));
  typedef long long K __attribute__((vector_size(8 * W)));
};

/// Lane operations on GCC vector types of W doubles; masks are vectors of -1 (true) / 0.
template <int W>
struct VecSimd {
  static constexpr int kWidth = W;
  static constexpr bool kTransposes = false;
  using V = typename VecTypes<W>::V;
  using K = typename VecTypes<W>::K;
  static TECIDO_BATCH_INLINE V load(const double* p) {
    V v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  static TECIDO_BATCH_INLINE V set1(double x) { return V{} + x; }
  static TECIDO_BATCH_INLINE K lt(V a, V b) { return a < b; }
  static TECIDO_BATCH_INLINE K le(V a, V b) { return a <= b; }
  static TECIDO_BATCH_INLINE V select(K k, V a, V b) { return k ? a : b; }
  static TECIDO_BATCH_INLINE V abs(V v) { return reinterpret_cast<V>(reinterpret_cast<K>(v) & 0x7FFFFFFFFFFFFFFFLL); }
  static TECIDO_BATCH_INLINE K all() { return ~K{}; }
  static TECIDO_BATCH_INLINE K none() { return K{}; }
  static TECIDO_BATCH_INLINE K kand(K a, K b) { return a & b; }
  static TECIDO_BATCH_INLINE K kor(K a, K b) { return a | b; }
  static TECIDO_BATCH_INLINE K knot(K a) { return ~a; }
  static TECIDO_BATCH_INLINE unsigned bits(K k) {
    unsigned m = 0;
    for (int l = 0; l < W; ++l) m |= (k[l] != 0 ? 1u : 0u) << l;
    return m;
  }
};

#if TECIDO_BATCH_X86
#define TECIDO_BATCH_AVX512_INLINE inline __attribute__((target("avx512f")))
/// Lane operations on AVX-512F registers of 8 doubles; masks are 8-bit mask registers.
struct Avx512Simd {
  static constexpr int kWidth = 8;
  static constexpr bool kTransposes = true;
  typedef __m512d V;
  typedef __mmask8 K;
  static TECIDO_BATCH_AVX512_INLINE V load(const double* p) { return _mm512_loadu_pd(p); }
  static TECIDO_BATCH_AVX512_INLINE V set1(double x) { return _mm512_set1_pd(x); }
  // Ordered, non-signalling: false when a lane holds NaN, as C++'s < and <= are.
  static TECIDO_BATCH_AVX512_INLINE K lt(V a, V b) { return _mm512_cmp_pd_mask(a, b, _CMP_LT_OQ); }
  static TECIDO_BATCH_AVX512_INLINE K le(V a, V b) { return _mm512_cmp_pd_mask(a, b, _CMP_LE_OQ); }
  static TECIDO_BATCH_AVX512_INLINE V select(K k, V a, V b) { return _mm512_mask_blend_pd(k, b, a); }
  static TECIDO_BATCH_AVX512_INLINE V abs(V v) { return _mm512_abs_pd(v); }
  static TECIDO_BATCH_AVX512_INLINE K all() { return 0xFF; }
  static TECIDO_BATCH_AVX512_INLINE K none() { return 0; }
  static TECIDO_BATCH_AVX512_INLINE K kand(K a, K b) { return static_cast<K>(a & b); }
  static TECIDO_BATCH_AVX512_INLINE K kor(K a, K b) { return static_cast<K>(a | b); }
  static TECIDO_BATCH_AVX512_INLINE K knot(K a) { return static_cast<K>(~a); }
  static TECIDO_BATCH_AVX512_INLINE unsigned bits(K k) { return k; }
  /// The points of up to eight queries (lanes n .. 8 repeat the last) from 64-byte vertex
  /// records x0 x y z, x1 x y z, pad, pad: one load per point and lane, then an 8 x 8
  /// transpose in registers (unpack, then two rounds of 128-bit block shuffles), instead of
  /// scalar stores read back as vectors. Pure data movement: the same values. (The maskz_
  /// forms with a full mask: GCC 12's plain forms trip -Wmaybe-uninitialized.)
  template <class P>
  static TECIDO_BATCH_AVX512_INLINE void load_records(const double* base, const std::array<int, 4>* q, int n, P& out) {
    for (int pt = 0; pt < 4; ++pt) {
      V r[8];
      for (int l = 0; l < 8; ++l) r[l] = _mm512_loadu_pd(base + 8 * static_cast<std::size_t>(q[l < n ? l : n - 1][pt]));
      V even[4], odd[4];  // even[k]: columns 0 2 4 6 of rows 2k, 2k + 1 interleaved; odd: 1 3 5 7
      for (int k = 0; k < 4; ++k) {
        even[k] = _mm512_maskz_unpacklo_pd(0xFF, r[2 * k], r[2 * k + 1]);
        odd[k] = _mm512_maskz_unpackhi_pd(0xFF, r[2 * k], r[2 * k + 1]);
      }
      // Rows 0-3 and 4-7 of columns {0, 4} and {2, 6} (even), {1, 5} and {3, 7} (odd).
      const V e04a = _mm512_maskz_shuffle_f64x2(0xFF, even[0], even[1], 0x88), e26a = _mm512_maskz_shuffle_f64x2(0xFF, even[0], even[1], 0xDD);
      const V e04b = _mm512_maskz_shuffle_f64x2(0xFF, even[2], even[3], 0x88), e26b = _mm512_maskz_shuffle_f64x2(0xFF, even[2], even[3], 0xDD);
      const V o15a = _mm512_maskz_shuffle_f64x2(0xFF, odd[0], odd[1], 0x88), o37a = _mm512_maskz_shuffle_f64x2(0xFF, odd[0], odd[1], 0xDD);
      const V o15b = _mm512_maskz_shuffle_f64x2(0xFF, odd[2], odd[3], 0x88), o37b = _mm512_maskz_shuffle_f64x2(0xFF, odd[2], odd[3], 0xDD);
      out.p[0][pt][0] = _mm512_maskz_shuffle_f64x2(0xFF, e04a, e04b, 0x88);  // column 0: x0.x
      out.p[1][pt][1] = _mm512_maskz_shuffle_f64x2(0xFF, e04a, e04b, 0xDD);  // column 4: x1.y
      out.p[0][pt][2] = _mm512_maskz_shuffle_f64x2(0xFF, e26a, e26b, 0x88);  // column 2: x0.z
      out.p[0][pt][1] = _mm512_maskz_shuffle_f64x2(0xFF, o15a, o15b, 0x88);  // column 1: x0.y
      out.p[1][pt][2] = _mm512_maskz_shuffle_f64x2(0xFF, o15a, o15b, 0xDD);  // column 5: x1.z
      out.p[1][pt][0] = _mm512_maskz_shuffle_f64x2(0xFF, o37a, o37b, 0x88);  // column 3: x1.x
    }
  }
};
#endif

/// std::min and std::max, lane by lane: the same choice (exact either way for finite input).
template <class S>
TECIDO_BATCH_INLINE typename S::V vmin(typename S::V a, typename S::V b) {
  return S::select(S::lt(b, a), b, a);
}
template <class S>
TECIDO_BATCH_INLINE typename S::V vmax(typename S::V a, typename S::V b) {
  return S::select(S::lt(a, b), b, a);
}

/// The points of one block of queries, lane by lane: p[time][point][coordinate][lane].
template <int W>
struct Staged {
  alignas(64) double p[2][4][3][W];
};

/// Writes the points of queries q[0 .. n) into s (lanes n .. W repeat the last query).
template <int W>
TECIDO_BATCH_INLINE void stage(const double* x0, const double* x1, std::size_t stride, const std::array<int, 4>* q,
                               int n, Staged<W>& s) {
  for (int l = 0; l < W; ++l) {
    const std::array<int, 4>& qq = q[l < n ? l : n - 1];
    for (int pt = 0; pt < 4; ++pt) {
      const std::size_t at = stride * static_cast<std::size_t>(qq[pt]);
      for (int c = 0; c < 3; ++c) {
        s.p[0][pt][c][l] = x0[at + c];
        s.p[1][pt][c][l] = x1[at + c];
      }
    }
  }
}

/// The points of one block in registers: p[time][point][coordinate], one lane per query.
template <class S>
struct Points {
  typename S::V p[2][4][3];
};

template <class S>
TECIDO_BATCH_INLINE void load_staged(const Staged<S::kWidth>& s, Points<S>& out) {
  for (int t = 0; t < 2; ++t)
    for (int pt = 0; pt < 4; ++pt)
      for (int c = 0; c < 3; ++c) out.p[t][pt][c] = S::load(s.p[t][pt][c]);
}

/// Boxes of two primitives at both frames: lo[frame][coordinate], hi likewise, per lane.
template <class S>
struct PairBoxes {
  typename S::V alo[2][3], ahi[2][3], blo[2][3], bhi[2][3];
};

/// The primitives' boxes of one block (ccd_pipeline.cpp's box_of: exact minima and maxima).
/// Kind K: 0 vertex-face (first primitive: point 0), 1 edge-edge (points 0 and 1).
template <class S, int K>
TECIDO_BATCH_INLINE void boxes_of(const Points<S>& s, PairBoxes<S>& b) {
  for (int t = 0; t < 2; ++t) {
    for (int c = 0; c < 3; ++c) {
      const auto p0 = s.p[t][0][c], p1 = s.p[t][1][c];
      const auto p2 = s.p[t][2][c], p3 = s.p[t][3][c];
      if (K == 0) {
        b.alo[t][c] = b.ahi[t][c] = p0;
        b.blo[t][c] = vmin<S>(p1, vmin<S>(p2, p3));
        b.bhi[t][c] = vmax<S>(p1, vmax<S>(p2, p3));
      } else {
        b.alo[t][c] = vmin<S>(p0, p1);
        b.ahi[t][c] = vmax<S>(p0, p1);
        b.blo[t][c] = vmin<S>(p2, p3);
        b.bhi[t][c] = vmax<S>(p2, p3);
      }
    }
  }
}

/// Swept boxes disjoint (ccd_pipeline.cpp's box_stages: the union of the two frames' boxes,
/// exact comparisons).
template <class S>
TECIDO_BATCH_INLINE typename S::K swept_disjoint(const PairBoxes<S>& b) {
  typename S::K dis = S::none();
  for (int c = 0; c < 3; ++c) {
    const auto alo = vmin<S>(b.alo[0][c], b.alo[1][c]), ahi = vmax<S>(b.ahi[0][c], b.ahi[1][c]);
    const auto blo = vmin<S>(b.blo[0][c], b.blo[1][c]), bhi = vmax<S>(b.bhi[0][c], b.bhi[1][c]);
    dis = S::kor(dis, S::kor(S::lt(ahi, blo), S::lt(bhi, alo)));
  }
  return dis;
}

/// The boxes overlap at t = 0 or at t = 1 (ccd_kinetic_boxes.cpp's first line): then the
/// kinetic test answers "not disjoint".
template <class S>
TECIDO_BATCH_INLINE typename S::K overlap_at_a_frame(const PairBoxes<S>& b) {
  typename S::K ov[2];
  for (int t = 0; t < 2; ++t) {
    ov[t] = S::all();
    for (int c = 0; c < 3; ++c)
      ov[t] = S::kand(ov[t], S::kand(S::le(b.alo[t][c], b.bhi[t][c]), S::le(b.blo[t][c], b.ahi[t][c])));
  }
  return S::kor(ov[0], ov[1]);
}

/// The rest of ccd_kinetic_boxes_disjoint (after its first line), lane by lane: the same
/// operations in the same order, its early returns turned into masks (they select, they do
/// not change any value computed).
template <class S>
TECIDO_BATCH_INLINE typename S::K kinetic_program_infeasible(const PairBoxes<S>& b) {
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

/// A 3-vector of lanes (templated on the traits: GCC ignores the attributes of __m512d as a
/// template argument).
template <class S>
struct V3 {
  typename S::V x, y, z;
};
template <class S>
TECIDO_BATCH_INLINE V3<S> cross(const V3<S>& a, const V3<S>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class S>
TECIDO_BATCH_INLINE typename S::V dot(const V3<S>& a, const V3<S>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

/// The cubic's verdict (ccd_system.h's differences, ccd_coplanarity_cubic.cpp's coefficients
/// and cheap bound, ccd_bernstein.h's certified sign), where ccd's scale is 1.
template <class S, int K>
TECIDO_BATCH_INLINE typename S::K cubic_miss(const Points<S>& s) {
  using V = typename S::V;
  // Difference vectors X, Y, Z as (minuend, subtrahend) points (ccd_system.cpp's kPairs).
  constexpr int kPairs[2][3][2] = {{{2, 1}, {3, 1}, {0, 1}}, {{1, 0}, {2, 3}, {2, 0}}};
  V3<S> d[2][3];
  V m[3];
  for (int v = 0; v < 3; ++v) {
    m[v] = S::set1(0.0);
    for (int t = 0; t < 2; ++t) {
      V e[3];
      for (int c = 0; c < 3; ++c) {
        e[c] = s.p[t][kPairs[K][v][0]][c] - s.p[t][kPairs[K][v][1]][c];
        m[v] = vmax<S>(m[v], S::abs(e[c]));
      }
      d[t][v] = {e[0], e[1], e[2]};
    }
  }
  const V3<S>&x0 = d[0][0], &x1 = d[1][0], &y0 = d[0][1], &y1 = d[1][1], &z0 = d[0][2], &z1 = d[1][2];
  const V3<S> c00 = cross(y0, z0), c11 = cross(y1, z1);
  const V3<S> a = cross(y1, z0), b = cross(y0, z1);
  const V3<S> sum = {a.x + b.x, a.y + b.y, a.z + b.z};
  const V three = S::set1(3.0);
  const V f0 = dot(x0, c00);
  const V f1 = (dot(x1, c00) + dot(x0, sum)) / three;
  const V f2 = (dot(x0, c11) + dot(x1, sum)) / three;
  const V f3 = dot(x1, c11);
  const V e0 = S::set1(0x1p-49 * (6.0 * (1.0 + 0x1p-50))) * (m[0] * m[1] * m[2]) + S::set1(0x1p-900);
  const V lo = vmin<S>(vmin<S>(f0, f1), vmin<S>(f2, f3)), hi = vmax<S>(vmax<S>(f0, f1), vmax<S>(f2, f3));
  const V big = vmax<S>(m[0], vmax<S>(m[1], m[2]));
  const auto unscaled = S::kand(S::le(S::set1(0x1p-128), big), S::le(big, S::set1(0x1p125)));
  return S::kand(unscaled, S::kor(S::lt(e0, lo), S::lt(hi, S::set1(0.0) - e0)));
}

/// The verdicts of one block of queries (lanes valid of them).
template <class S, int K>
TECIDO_BATCH_INLINE void decide_block(const Points<S>& s, int lanes, bool cubic, std::uint8_t* verdict) {
  constexpr int W = S::kWidth;
  PairBoxes<S> b;
  boxes_of<S, K>(s, b);
  unsigned disjoint = S::bits(swept_disjoint<S>(b));
  // The linear program only where some lane needs it (most neighbours overlap at a frame).
  const unsigned open = ~disjoint & ~S::bits(overlap_at_a_frame<S>(b)) & ((1u << W) - 1);
  if (open) disjoint |= open & S::bits(kinetic_program_infeasible<S>(b));
  const unsigned open_lanes = ~disjoint & ((1u << lanes) - 1);
  const unsigned miss = cubic && open_lanes ? open_lanes & S::bits(cubic_miss<S, K>(s)) : 0u;
  for (int l = 0; l < lanes; ++l)
    verdict[l] = static_cast<std::uint8_t>(((disjoint >> l) & 1u ? kCcdBoxesDisjoint : 0) |
                                           ((miss >> l) & 1u ? kCcdCubicMiss : 0));
}

/// The verdicts of queries q[0 .. n) of kind K.
template <class S, int K>
TECIDO_BATCH_INLINE void run_blocks(const double* x0, const double* x1, std::size_t stride, const std::array<int, 4>* q,
                                    int n, bool cubic, std::uint8_t* verdict) {
  constexpr int W = S::kWidth;
  Points<S> pts;
  if constexpr (S::kTransposes) {
    if (x1 == x0 + 3 && stride == 8) {  // a vertex's two frames in one 64-byte record
      for (int k = 0; k < n; k += W) {
        const int lanes = std::min(W, n - k);
        S::load_records(x0, q + k, lanes, pts);
        decide_block<S, K>(pts, lanes, cubic, verdict + k);
      }
      return;
    }
  }
  // Double-buffered: the next block's points are written while this block's, written one
  // block earlier, are read back as vectors (a wide load of fresh narrow stores would wait
  // for them to leave the store buffer).
  Staged<W> staged[2];
  stage<W>(x0, x1, stride, q, std::min(W, n), staged[0]);
  for (int k = 0, buf = 0; k < n; k += W, buf ^= 1) {
    const int lanes = std::min(W, n - k);
    if (k + W < n) stage<W>(x0, x1, stride, q + k + W, std::min(W, n - k - W), staged[buf ^ 1]);
    load_staged<S>(staged[buf], pts);
    decide_block<S, K>(pts, lanes, cubic, verdict + k);
  }
}

using StagesKernel = void (*)(const double*, const double*, std::size_t, const std::array<int, 4>*, int, bool,
                              std::uint8_t*);

template <class S, int K>
void stages(const double* x0, const double* x1, std::size_t stride, const std::array<int, 4>* q, int n, bool cubic,
            std::uint8_t* out) {
  run_blocks<S, K>(x0, x1, stride, q, n, cubic, out);
}
#if TECIDO_BATCH_X86
template <class S, int K>
TECIDO_BATCH_TARGET_AVX void stages_avx(const double* x0, const double* x1, std::size_t stride,
                                        const std::array<int, 4>* q, int n, bool cubic, std::uint8_t* out) {
  run_blocks<S, K>(x0, x1, stride, q, n, cubic, out);
}
template <int K>
TECIDO_BATCH_TARGET_AVX512 void stages_avx512(const double* x0, const double* x1, std::size_t stride,
                                              const std::array<int, 4>* q, int n, bool cubic, std::uint8_t* out) {
  run_blocks<Avx512Simd, K>(x0, x1, stride, q, n, cubic, out);
}
#endif

}  // namespace

bool ccd_batch_width_available(int width) {
  if (width == 2) return true;
#if TECIDO_BATCH_X86
  // __builtin_cpu_init: safe even when called from a static initializer, before libgcc's own.
  __builtin_cpu_init();
  if (width == 4) return __builtin_cpu_supports("avx");
  if (width == 8) return __builtin_cpu_supports("avx512f");
#endif
  return false;
}

int ccd_batch_widest() {
  static const int widest = ccd_batch_width_available(8) ? 8 : (ccd_batch_width_available(4) ? 4 : 2);
  return widest;
}

void ccd_batch_first_stages(CcdKind kind, const double* x0, const double* x1, std::size_t stride,
                            const std::array<int, 4>* queries, int n, bool cubic, std::uint8_t* verdict, int width) {
  if (n <= 0) return;
  if (width == 0) width = ccd_batch_widest();
  const bool vf = kind == CcdKind::VertexFace;
  StagesKernel k = vf ? &stages<VecSimd<2>, 0> : &stages<VecSimd<2>, 1>;
#if TECIDO_BATCH_X86
  if (width == 4) k = vf ? &stages_avx<VecSimd<4>, 0> : &stages_avx<VecSimd<4>, 1>;
  if (width == 8) k = vf ? &stages_avx512<0> : &stages_avx512<1>;
#endif
  k(x0, x1, stride, queries, n, cubic, verdict);
}

}  // namespace tecido
