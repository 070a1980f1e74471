#pragma once
/// Width 8 of core's SIMD layer: lane operations on AVX-512F registers of 8 doubles, masks in
/// 8-bit mask registers. Intrinsics rather than GCC vector types: GCC 12 expands vector-type
/// comparisons lane by lane at this width, as AVX-512F keeps comparison results in mask
/// registers. Each member carries target("avx512f") itself, so the type can be defined once,
/// outside the per-width regions (core/simd/target.h), and inlined into the AVX-512 copies.
#include "core/simd/target.h"

#if TECIDO_SIMD_X86
#include <immintrin.h>

namespace tecido {
namespace simd {

#define TECIDO_SIMD_AVX512_INLINE TECIDO_SIMD_TARGET_INLINE("avx512f")

struct Avx512Lanes {
  static constexpr int kWidth = 8;
  static constexpr bool kTransposes = true;  ///< has transpose_8x6
  typedef __m512d V;
  typedef __mmask8 K;
  static TECIDO_SIMD_AVX512_INLINE V load(const double* p) { return _mm512_loadu_pd(p); }
  static TECIDO_SIMD_AVX512_INLINE V set1(double x) { return _mm512_set1_pd(x); }
  static TECIDO_SIMD_AVX512_INLINE void store(double* p, V v) { _mm512_storeu_pd(p, v); }
  /// Lane l: base[idx[l]] (one gather instruction).
  static TECIDO_SIMD_AVX512_INLINE V gather(const double* base, const int* idx) {
    const __m256i i = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(idx));
    return _mm512_mask_i32gather_pd(_mm512_setzero_pd(), 0xFF, i, base, 8);
  }
  /// Round toward -infinity (imm 0x09: round down, exceptions suppressed), exact as std::floor.
  static TECIDO_SIMD_AVX512_INLINE V floor(V v) { return _mm512_maskz_roundscale_pd(0xFF, v, 0x09); }
  static TECIDO_SIMD_AVX512_INLINE V sqrt(V v) { return _mm512_maskz_sqrt_pd(0xFF, v); }
  // Ordered, non-signalling: false when a lane holds NaN, as C++'s < and <= are.
  static TECIDO_SIMD_AVX512_INLINE K lt(V a, V b) { return _mm512_cmp_pd_mask(a, b, _CMP_LT_OQ); }
  static TECIDO_SIMD_AVX512_INLINE K le(V a, V b) { return _mm512_cmp_pd_mask(a, b, _CMP_LE_OQ); }
  static TECIDO_SIMD_AVX512_INLINE V select(K k, V a, V b) { return _mm512_mask_blend_pd(k, b, a); }
  static TECIDO_SIMD_AVX512_INLINE V abs(V v) { return _mm512_abs_pd(v); }
  static TECIDO_SIMD_AVX512_INLINE K all() { return 0xFF; }
  static TECIDO_SIMD_AVX512_INLINE K none() { return 0; }
  static TECIDO_SIMD_AVX512_INLINE K kand(K a, K b) { return static_cast<K>(a & b); }
  static TECIDO_SIMD_AVX512_INLINE K kor(K a, K b) { return static_cast<K>(a | b); }
  static TECIDO_SIMD_AVX512_INLINE K knot(K a) { return static_cast<K>(~a); }
  static TECIDO_SIMD_AVX512_INLINE unsigned bits(K k) { return k; }
  /// Columns 0 .. 5 of eight rows of 8 doubles (row l at rows[l]): one load per row, then an
  /// 8 x 8 transpose in registers (unpack, then two rounds of 128-bit block shuffles), instead
  /// of scalar stores read back as vectors. Pure data movement: the same values. (The maskz_
  /// forms with a full mask: GCC 12's plain forms trip -Wmaybe-uninitialized.)
  static TECIDO_SIMD_AVX512_INLINE void transpose_8x6(const double* const (&rows)[8], V (&col)[6]) {
    V r[8];
    for (int l = 0; l < 8; ++l) r[l] = _mm512_loadu_pd(rows[l]);
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
    col[0] = _mm512_maskz_shuffle_f64x2(0xFF, e04a, e04b, 0x88);
    col[4] = _mm512_maskz_shuffle_f64x2(0xFF, e04a, e04b, 0xDD);
    col[2] = _mm512_maskz_shuffle_f64x2(0xFF, e26a, e26b, 0x88);
    col[1] = _mm512_maskz_shuffle_f64x2(0xFF, o15a, o15b, 0x88);
    col[5] = _mm512_maskz_shuffle_f64x2(0xFF, o15a, o15b, 0xDD);
    col[3] = _mm512_maskz_shuffle_f64x2(0xFF, o37a, o37b, 0x88);
  }
};

}  // namespace simd
}  // namespace tecido
#endif
