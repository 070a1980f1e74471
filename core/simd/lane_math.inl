/// Small algebra on lanes shared by core's kernels at every width: min and max as std::min and
/// std::max choose, and 3-vectors of lanes with their cross and dot products.
// A per-width file (core/simd/target.h): included inside each width's namespace (and target
// region) before the kernels that use it. No include guard, no includes, no namespace.

/// std::min and std::max, lane by lane: the same choice (exact either way for finite input).
template <class S>
TECIDO_SIMD_INLINE typename S::V vmin(typename S::V a, typename S::V b) {
  return S::select(S::lt(b, a), b, a);
}
template <class S>
TECIDO_SIMD_INLINE typename S::V vmax(typename S::V a, typename S::V b) {
  return S::select(S::lt(a, b), b, a);
}

/// A 3-vector of lanes (templated on the lane type: GCC ignores the attributes of __m512d as a
/// template argument).
template <class S>
struct V3 {
  typename S::V x, y, z;
};
template <class S>
TECIDO_SIMD_INLINE V3<S> add(const V3<S>& a, const V3<S>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class S>
TECIDO_SIMD_INLINE V3<S> cross(const V3<S>& a, const V3<S>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class S>
TECIDO_SIMD_INLINE typename S::V dot(const V3<S>& a, const V3<S>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
/// The permanent of the cross product: |a| x |b| with + in place of -.
template <class S>
TECIDO_SIMD_INLINE V3<S> cross_abs(const V3<S>& a, const V3<S>& b) {
  return {S::abs(a.y * b.z) + S::abs(a.z * b.y), S::abs(a.z * b.x) + S::abs(a.x * b.z),
          S::abs(a.x * b.y) + S::abs(a.y * b.x)};
}
/// |a| . b (b already nonnegative: a permanent).
template <class S>
TECIDO_SIMD_INLINE typename S::V dot_abs(const V3<S>& a, const V3<S>& b) {
  return S::abs(a.x) * b.x + S::abs(a.y) * b.y + S::abs(a.z) * b.z;
}
