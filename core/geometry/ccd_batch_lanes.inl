/// Lane operations of core's batched continuous collision stages on GCC vector types (the
/// baseline and AVX widths), and the small helpers every width's kernels share.
// Included by ccd_batch_kernels.inl only, once per width, inside that width's namespace and
// target region (ccd_batch_simd.h says why): no include guard, no includes, no namespace.

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
