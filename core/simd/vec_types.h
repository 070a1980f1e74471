#pragma once
/// GCC (and clang) vector types of W doubles and of W 64-bit integers, the registers of core's
/// SIMD layer at widths 2 (SSE2) and 4 (AVX) (vec_lanes.inl).

namespace tecido {
namespace simd {

/// Comparison results are vectors of -1 (true) and 0 (false).
template <int W>
struct VecTypes {
  typedef double V __attribute__((vector_size(8 * W)));
  typedef long long K __attribute__((vector_size(8 * W)));
};

}  // namespace simd
}  // namespace tecido
