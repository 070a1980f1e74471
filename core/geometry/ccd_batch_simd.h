#pragma once
/// Lane operations for core's batched continuous collision stages (ccd_batch_stages.cpp):
/// internal, included only by that source file.
///
/// The kernels are written once against a small set of lane operations (a "Simd" traits
/// class: loads, arithmetic, ordered comparisons giving masks, selection) and compiled three
/// times: baseline (2 lanes, SSE2, through GCC vector types), AVX (4 lanes, GCC vector types)
/// and AVX-512F (8 lanes, intrinsics: GCC 12 expands vector-type comparisons lane by lane
/// there, as AVX-512F keeps comparison results in mask registers). Every lane runs the scalar
/// code's operations in its order (IEEE-754, round to nearest); no multiply-add is fused, as
/// the build compiles with -ffp-contract=off (AVX-512F has FMA; the baseline and AVX have none).
///
/// Each width is its own copy of the templates (ccd_batch_kernels.inl, included once per width
/// by ccd_batch_stages.cpp, each in its own namespace) compiled between
/// TECIDO_BATCH_BEGIN_TARGET(...) and TECIDO_BATCH_END_TARGET, so that every function a wide
/// kernel calls carries the kernel's instruction set: a wide vector never crosses a call
/// between functions of different sets, which clang rejects (it checks the vector calling
/// convention before inlining) and GCC warns about. The baseline copy has no target at all.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>

#if defined(__GNUC__) && defined(__x86_64__)
#define TECIDO_BATCH_X86 1
#include <immintrin.h>
#define TECIDO_BATCH_PRAGMA(x) _Pragma(#x)
#if defined(__clang__)
#define TECIDO_BATCH_BEGIN_TARGET(isa) \
  TECIDO_BATCH_PRAGMA(clang attribute push(__attribute__((target(isa))), apply_to = function))
#define TECIDO_BATCH_END_TARGET _Pragma("clang attribute pop")
#else
#define TECIDO_BATCH_BEGIN_TARGET(isa) _Pragma("GCC push_options") TECIDO_BATCH_PRAGMA(GCC target(isa))
#define TECIDO_BATCH_END_TARGET _Pragma("GCC pop_options")
#endif
#else
#define TECIDO_BATCH_X86 0
#endif
#define TECIDO_BATCH_INLINE inline __attribute__((always_inline))

namespace tecido {
namespace ccd_batch {

/// GCC vector types of W doubles and of W 64-bit integers (comparison results: -1 true, 0 false).
template <int W>
struct VecTypes {
  typedef double V __attribute__((vector_size(8 * W)));
  typedef long long K __attribute__((vector_size(8 * W)));
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

}  // namespace ccd_batch
}  // namespace tecido
