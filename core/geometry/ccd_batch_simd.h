#pragma once
/// Lane operations for core's batched continuous collision stages (ccd_batch_stages.cpp,
/// ccd_batch_root.h): internal, included only by those kernels' source file.
///
/// The kernels are written once against a small set of lane operations (a "Simd" traits
/// class: loads, arithmetic, ordered comparisons giving masks, selection) and compiled three
/// times: baseline (2 lanes, SSE2, through GCC vector types), AVX (4 lanes, GCC vector types)
/// and AVX-512F (8 lanes, intrinsics: GCC 12 expands vector-type comparisons lane by lane
/// there, as AVX-512F keeps comparison results in mask registers). Every lane runs the scalar
/// code's operations in its order (IEEE-754, round to nearest); fp-contract is off in the wide
/// functions so that no multiply-add is fused (AVX-512F has FMA; the baseline and AVX have none
/// to fuse into).
#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>

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
namespace ccd_batch {

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
  static TECIDO_BATCH_INLINE void store(double* p, V v) { std::memcpy(p, &v, sizeof v); }
  static TECIDO_BATCH_INLINE V floor(V v) {
    for (int l = 0; l < W; ++l) v[l] = std::floor(v[l]);
    return v;
  }
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
  static TECIDO_BATCH_AVX512_INLINE void store(double* p, V v) { _mm512_storeu_pd(p, v); }
  /// Round toward -infinity (imm 0x09: round down, exceptions suppressed), exact as std::floor.
  static TECIDO_BATCH_AVX512_INLINE V floor(V v) { return _mm512_maskz_roundscale_pd(0xFF, v, 0x09); }
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
    const int last = n > 1 ? n - 1 : 0;
    for (int pt = 0; pt < 4; ++pt) {
      V r[8];
      for (int l = 0; l < 8; ++l) r[l] = _mm512_loadu_pd(base + 8 * static_cast<std::size_t>(q[l < n ? l : last][pt]));
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

/// The points of one block of queries in registers: p[time][point][coordinate], one lane per
/// query (points in the order of ccd_query.h).
template <class S>
struct Points {
  typename S::V p[2][4][3];
};

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

}  // namespace ccd_batch
}  // namespace tecido
