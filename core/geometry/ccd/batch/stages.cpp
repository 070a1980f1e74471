#include "core/geometry/ccd/batch/stages.h"

#include "core/geometry/ccd/settings.h"
#include "core/simd/dispatch.h"
#include "core/simd/widths.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

namespace tecido {

namespace {

// One copy of the kernels per width, each in its own namespace and compiled for its
// instruction set (core/simd/for_each_width.inl).
#define TECIDO_SIMD_KERNEL "core/geometry/ccd/batch/kernels.inl"
#include "core/simd/for_each_width.inl"

using StagesKernel = void (*)(const double*, const double*, std::size_t, const std::array<int, 4>*, int, bool,
                              std::uint8_t*);

/// The entry point of kind K (0 vertex-face, 1 edge-edge) at a width.
template <int K>
StagesKernel kernel(int width) {
#if TECIDO_SIMD_X86
  return simd::pick<StagesKernel>(width, &simd1::stages<simd1::Lanes, K>, &simd2::stages<simd2::Lanes, K>,
                                  &simd4::stages<simd4::Lanes, K>, &simd8::stages<simd8::Lanes, K>);
#else
  return simd::pick<StagesKernel>(width, &simd1::stages<simd1::Lanes, K>, &simd2::stages<simd2::Lanes, K>, nullptr,
                                  nullptr);
#endif
}

}  // namespace

bool ccd_batch_width_available(int width) { return simd::width_available(width); }

int ccd_batch_widest() {
  static const int widest = simd::widest_width(2, 8);
  return widest;
}

void ccd_batch_first_stages(CcdKind kind, const double* x0, const double* x1, std::size_t stride,
                            const std::array<int, 4>* queries, int n, bool cubic, std::uint8_t* verdict, int width) {
  if (n <= 0) return;
  if (width == 0) width = ccd_batch_widest();
  const StagesKernel k = kind == CcdKind::VertexFace ? kernel<0>(width) : kernel<1>(width);
  k(x0, x1, stride, queries, n, cubic, verdict);
}

}  // namespace tecido
