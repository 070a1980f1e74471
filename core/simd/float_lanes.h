#pragma once
/// Single-precision lanes of core's SIMD layer, for kernels on float boxes (the box tree's
/// node-pair masks, core/cloth/triangle_bvh.cpp): width 1 (scalar), 4 (SSE2, one 128-bit
/// register) and 16 (AVX-512F), with 32-bit integer lanes beside them (vertex ids).
///
/// The 4 x 4 pairing of two nodes' lanes: lane i of a pass stands for lane i / 4 of node a and
/// lane i % 4 of node b. pair_a(row, pass) and pair_b(row, pass) load a node's row of four in
/// that arrangement; kPasses passes cover the 16 pairs (16 / kWidth). min and max choose as
/// SSE's minps / maxps do (the second operand when unordered), at every width.
#include "core/simd/target.h"

#include <cmath>
#include <cstring>

#if TECIDO_SIMD_X86
#include <immintrin.h>
#endif

namespace tecido {
namespace simd {

/// One float; masks are bools.
struct ScalarFloatLanes {
  static constexpr int kWidth = 1;
  static constexpr int kPasses = 16;
  using V = float;
  using K = bool;
  using I = int;
  static TECIDO_SIMD_INLINE V load(const float* p) { return *p; }
  static TECIDO_SIMD_INLINE void store(float* p, V v) { *p = v; }
  static TECIDO_SIMD_INLINE V set1(float x) { return x; }
  static TECIDO_SIMD_INLINE I loadi(const int* p) { return *p; }
  static TECIDO_SIMD_INLINE I set1i(int x) { return x; }
  static TECIDO_SIMD_INLINE V pair_a(const float* row, int pass) { return row[pass / 4]; }
  static TECIDO_SIMD_INLINE V pair_b(const float* row, int pass) { return row[pass % 4]; }
  static TECIDO_SIMD_INLINE I pair_ai(const int* row, int pass) { return row[pass / 4]; }
  static TECIDO_SIMD_INLINE I pair_bi(const int* row, int pass) { return row[pass % 4]; }
  static TECIDO_SIMD_INLINE V abs(V v) { return std::fabs(v); }
  static TECIDO_SIMD_INLINE V max(V a, V b) { return a > b ? a : b; }
  static TECIDO_SIMD_INLINE V min(V a, V b) { return a < b ? a : b; }
  static TECIDO_SIMD_INLINE K lt(V a, V b) { return a < b; }
  static TECIDO_SIMD_INLINE K le(V a, V b) { return a <= b; }
  static TECIDO_SIMD_INLINE K eqi(I a, I b) { return a == b; }
  static TECIDO_SIMD_INLINE V select(K k, V a, V b) { return k ? a : b; }
  static TECIDO_SIMD_INLINE K all() { return true; }
  static TECIDO_SIMD_INLINE K none() { return false; }
  static TECIDO_SIMD_INLINE K kand(K a, K b) { return a && b; }
  static TECIDO_SIMD_INLINE K kor(K a, K b) { return a || b; }
  static TECIDO_SIMD_INLINE K kandnot(K a, K b) { return !a && b; }  ///< ~a & b
  static TECIDO_SIMD_INLINE unsigned bits(K k) { return k ? 1u : 0u; }
};

#if TECIDO_SIMD_X86
/// Four floats in an SSE register (part of x86-64: no target needed); masks are registers of
/// all-ones / zero lanes.
struct Sse2FloatLanes {
  static constexpr int kWidth = 4;
  static constexpr int kPasses = 4;
  using V = __m128;
  using K = __m128;
  using I = __m128i;
  static TECIDO_SIMD_INLINE V load(const float* p) { return _mm_loadu_ps(p); }
  static TECIDO_SIMD_INLINE void store(float* p, V v) { _mm_storeu_ps(p, v); }
  static TECIDO_SIMD_INLINE V set1(float x) { return _mm_set1_ps(x); }
  static TECIDO_SIMD_INLINE I loadi(const int* p) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p)); }
  static TECIDO_SIMD_INLINE I set1i(int x) { return _mm_set1_epi32(x); }
  static TECIDO_SIMD_INLINE V pair_a(const float* row, int pass) { return _mm_set1_ps(row[pass]); }
  static TECIDO_SIMD_INLINE V pair_b(const float* row, int) { return _mm_loadu_ps(row); }
  static TECIDO_SIMD_INLINE I pair_ai(const int* row, int pass) { return _mm_set1_epi32(row[pass]); }
  static TECIDO_SIMD_INLINE I pair_bi(const int* row, int) { return loadi(row); }
  static TECIDO_SIMD_INLINE V abs(V v) { return _mm_andnot_ps(_mm_set1_ps(-0.0f), v); }
  static TECIDO_SIMD_INLINE V max(V a, V b) { return _mm_max_ps(a, b); }
  static TECIDO_SIMD_INLINE V min(V a, V b) { return _mm_min_ps(a, b); }
  static TECIDO_SIMD_INLINE K lt(V a, V b) { return _mm_cmplt_ps(a, b); }
  static TECIDO_SIMD_INLINE K le(V a, V b) { return _mm_cmple_ps(a, b); }
  static TECIDO_SIMD_INLINE K eqi(I a, I b) { return _mm_castsi128_ps(_mm_cmpeq_epi32(a, b)); }
  static TECIDO_SIMD_INLINE V select(K k, V a, V b) { return _mm_or_ps(_mm_and_ps(k, a), _mm_andnot_ps(k, b)); }
  static TECIDO_SIMD_INLINE K all() { return _mm_castsi128_ps(_mm_set1_epi32(-1)); }
  static TECIDO_SIMD_INLINE K none() { return _mm_setzero_ps(); }
  static TECIDO_SIMD_INLINE K kand(K a, K b) { return _mm_and_ps(a, b); }
  static TECIDO_SIMD_INLINE K kor(K a, K b) { return _mm_or_ps(a, b); }
  static TECIDO_SIMD_INLINE K kandnot(K a, K b) { return _mm_andnot_ps(a, b); }
  static TECIDO_SIMD_INLINE unsigned bits(K k) { return static_cast<unsigned>(_mm_movemask_ps(k)); }
};

#define TECIDO_SIMD_AVX512F_INLINE TECIDO_SIMD_TARGET_INLINE("avx512f")
/// Sixteen floats in an AVX-512 register, masks in 16-bit mask registers; one pass covers the
/// 16 pairs of two nodes (a's row repeated, b's row tiled). (The maskz_ forms with a full mask:
/// GCC 12's plain broadcast / permutexvar / max trip -Wuninitialized.)
struct Avx512FloatLanes {
  static constexpr int kWidth = 16;
  static constexpr int kPasses = 1;
  using V = __m512;
  using K = __mmask16;
  using I = __m512i;
  static TECIDO_SIMD_AVX512F_INLINE V set1(float x) { return _mm512_set1_ps(x); }
  static TECIDO_SIMD_AVX512F_INLINE V pair_b(const float* row, int) {
    return _mm512_maskz_broadcast_f32x4(0xFFFF, _mm_loadu_ps(row));
  }
  static TECIDO_SIMD_AVX512F_INLINE V pair_a(const float* row, int pass) {
    const __m512i rep = _mm512_set_epi32(3, 3, 3, 3, 2, 2, 2, 2, 1, 1, 1, 1, 0, 0, 0, 0);
    return _mm512_maskz_permutexvar_ps(0xFFFF, rep, pair_b(row, pass));
  }
  static TECIDO_SIMD_AVX512F_INLINE I pair_bi(const int* row, int) {
    return _mm512_maskz_broadcast_i32x4(0xFFFF, _mm_loadu_si128(reinterpret_cast<const __m128i*>(row)));
  }
  static TECIDO_SIMD_AVX512F_INLINE I pair_ai(const int* row, int pass) {
    const __m512i rep = _mm512_set_epi32(3, 3, 3, 3, 2, 2, 2, 2, 1, 1, 1, 1, 0, 0, 0, 0);
    return _mm512_maskz_permutexvar_epi32(0xFFFF, rep, pair_bi(row, pass));
  }
  static TECIDO_SIMD_AVX512F_INLINE V abs(V v) { return _mm512_abs_ps(v); }
  static TECIDO_SIMD_AVX512F_INLINE V max(V a, V b) { return _mm512_maskz_max_ps(0xFFFF, a, b); }
  static TECIDO_SIMD_AVX512F_INLINE V min(V a, V b) { return _mm512_maskz_min_ps(0xFFFF, a, b); }
  static TECIDO_SIMD_AVX512F_INLINE K lt(V a, V b) { return _mm512_cmp_ps_mask(a, b, _CMP_LT_OQ); }
  static TECIDO_SIMD_AVX512F_INLINE K le(V a, V b) { return _mm512_cmp_ps_mask(a, b, _CMP_LE_OQ); }
  static TECIDO_SIMD_AVX512F_INLINE K eqi(I a, I b) { return _mm512_cmpeq_epi32_mask(a, b); }
  static TECIDO_SIMD_AVX512F_INLINE V select(K k, V a, V b) { return _mm512_mask_blend_ps(k, b, a); }
  static TECIDO_SIMD_AVX512F_INLINE K all() { return 0xFFFF; }
  static TECIDO_SIMD_AVX512F_INLINE K none() { return 0; }
  static TECIDO_SIMD_AVX512F_INLINE K kand(K a, K b) { return static_cast<K>(a & b); }
  static TECIDO_SIMD_AVX512F_INLINE K kor(K a, K b) { return static_cast<K>(a | b); }
  static TECIDO_SIMD_AVX512F_INLINE K kandnot(K a, K b) { return static_cast<K>(~a & b); }
  static TECIDO_SIMD_AVX512F_INLINE unsigned bits(K k) { return k; }
};
#endif

/// The float lanes of the baseline (no run-time dispatch needed): SSE2 on x86-64, else scalar.
#if TECIDO_SIMD_X86
using BaselineFloatLanes = Sse2FloatLanes;
#else
using BaselineFloatLanes = ScalarFloatLanes;
#endif

}  // namespace simd
}  // namespace tecido
