/// Widths 2 (SSE2) and 4 (AVX) of core's SIMD layer: lane operations on GCC vector types.
// A per-width file (core/simd/target.h): for_each_width.inl includes it inside each width's
// namespace and target region, so that its functions carry that width's instruction set. No
// include guard, no includes, no namespace.

/// Lane operations on GCC vector types of W doubles; masks are vectors of -1 (true) / 0.
template <int W>
struct VecLanes {
  static constexpr int kWidth = W;
  static constexpr bool kTransposes = false;
  using V = typename ::tecido::simd::VecTypes<W>::V;
  using K = typename ::tecido::simd::VecTypes<W>::K;
  static TECIDO_SIMD_INLINE V load(const double* p) {
    V v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  static TECIDO_SIMD_INLINE V set1(double x) { return V{} + x; }
  static TECIDO_SIMD_INLINE void store(double* p, V v) { std::memcpy(p, &v, sizeof v); }
  /// Lane l: base[idx[l]].
  static TECIDO_SIMD_INLINE V gather(const double* base, const int* idx) {
    V v;
    for (int l = 0; l < W; ++l) v[l] = base[idx[l]];
    return v;
  }
  static TECIDO_SIMD_INLINE V floor(V v) {
    for (int l = 0; l < W; ++l) v[l] = std::floor(v[l]);
    return v;
  }
  /// Correctly rounded, as std::sqrt (one instruction on x86: the lane loop is not vectorized).
  static TECIDO_SIMD_INLINE V sqrt(V v) {
#if TECIDO_SIMD_X86
    if constexpr (W == 2) {
      return (V)_mm_sqrt_pd((__m128d)v);
    } else if constexpr (W == 4) {
      return (V)_mm256_sqrt_pd((__m256d)v);
    }
#endif
    for (int l = 0; l < W; ++l) v[l] = std::sqrt(v[l]);
    return v;
  }
  static TECIDO_SIMD_INLINE K lt(V a, V b) { return a < b; }
  static TECIDO_SIMD_INLINE K le(V a, V b) { return a <= b; }
  static TECIDO_SIMD_INLINE V select(K k, V a, V b) { return k ? a : b; }
  static TECIDO_SIMD_INLINE V abs(V v) { return reinterpret_cast<V>(reinterpret_cast<K>(v) & 0x7FFFFFFFFFFFFFFFLL); }
  static TECIDO_SIMD_INLINE K all() { return ~K{}; }
  static TECIDO_SIMD_INLINE K none() { return K{}; }
  static TECIDO_SIMD_INLINE K kand(K a, K b) { return a & b; }
  static TECIDO_SIMD_INLINE K kor(K a, K b) { return a | b; }
  static TECIDO_SIMD_INLINE K knot(K a) { return ~a; }
  static TECIDO_SIMD_INLINE unsigned bits(K k) {
    unsigned m = 0;
    for (int l = 0; l < W; ++l) m |= (k[l] != 0 ? 1u : 0u) << l;
    return m;
  }
};
