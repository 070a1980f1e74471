#pragma once
/// Width 1 of core's SIMD layer: the lane type whose "vector" is one double and whose mask is a
/// bool. A kernel instantiated with it is the scalar code (the same operations on the same
/// doubles in the same order as every wider instantiation), so a scalar caller and the vector
/// kernels share one text (core/simd/target.h).
#include "core/simd/target.h"

#include <cmath>

namespace tecido {
namespace simd {

struct ScalarLanes {
  static constexpr int kWidth = 1;
  static constexpr bool kTransposes = false;  ///< no in-register transpose (avx512_lanes.h)
  using V = double;
  using K = bool;
  static TECIDO_SIMD_INLINE V load(const double* p) { return *p; }
  static TECIDO_SIMD_INLINE V set1(double x) { return x; }
  static TECIDO_SIMD_INLINE void store(double* p, V v) { *p = v; }
  /// base[idx[0]] (a gather of one).
  static TECIDO_SIMD_INLINE V gather(const double* base, const int* idx) { return base[idx[0]]; }
  static TECIDO_SIMD_INLINE V floor(V v) { return std::floor(v); }
  static TECIDO_SIMD_INLINE V sqrt(V v) { return std::sqrt(v); }
  static TECIDO_SIMD_INLINE K lt(V a, V b) { return a < b; }
  static TECIDO_SIMD_INLINE K le(V a, V b) { return a <= b; }
  static TECIDO_SIMD_INLINE V select(K k, V a, V b) { return k ? a : b; }
  static TECIDO_SIMD_INLINE V abs(V v) { return std::fabs(v); }
  static TECIDO_SIMD_INLINE K all() { return true; }
  static TECIDO_SIMD_INLINE K none() { return false; }
  static TECIDO_SIMD_INLINE K kand(K a, K b) { return a && b; }
  static TECIDO_SIMD_INLINE K kor(K a, K b) { return a || b; }
  static TECIDO_SIMD_INLINE K knot(K a) { return !a; }
  static TECIDO_SIMD_INLINE unsigned bits(K k) { return k ? 1u : 0u; }
};

}  // namespace simd
}  // namespace tecido
