#include "core/geometry/ccd_batch_stages.h"

#include "core/geometry/ccd_batch_simd.h"

#include "core/platform/simd_level.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace tecido {

namespace {

using namespace ccd_batch;

// One copy of the kernels per width, each in its own namespace; the wide copies are compiled
// for their instruction set, the baseline copy for the build's (ccd_batch_simd.h).
namespace lanes2 {
#include "core/geometry/ccd_batch_kernels.inl"
}  // namespace lanes2
#if TECIDO_BATCH_X86
TECIDO_BATCH_BEGIN_TARGET("avx")
namespace lanes4 {
#include "core/geometry/ccd_batch_kernels.inl"
}  // namespace lanes4
TECIDO_BATCH_END_TARGET
TECIDO_BATCH_BEGIN_TARGET("avx512f")
namespace lanes8 {
#include "core/geometry/ccd_batch_kernels.inl"
}  // namespace lanes8
TECIDO_BATCH_END_TARGET
#endif

using StagesKernel = void (*)(const double*, const double*, std::size_t, const std::array<int, 4>*, int, bool,
                              std::uint8_t*);

}  // namespace

bool ccd_batch_width_available(int width) {
  if (width == 2) return true;
#if TECIDO_BATCH_X86
  // The CPU has the set and TECIDO_SIMD allows it (core/platform/simd_level.h).
  if (width == 4) return simd_level_allowed(SimdLevel::AVX);
  if (width == 8) return simd_level_allowed(SimdLevel::AVX512);
#endif
  return false;
}

int ccd_batch_widest() {
  static const int widest = ccd_batch_width_available(8) ? 8 : (ccd_batch_width_available(4) ? 4 : 2);
  return widest;
}

void ccd_batch_first_stages(CcdKind kind, const double* x0, const double* x1, std::size_t stride,
                            const std::array<int, 4>* queries, int n, bool cubic, std::uint8_t* verdict, int width) {
  if (n <= 0) return;
  if (width == 0) width = ccd_batch_widest();
  const bool vf = kind == CcdKind::VertexFace;
  using lanes2::VecSimd;
  StagesKernel k = vf ? &lanes2::stages<VecSimd<2>, 0> : &lanes2::stages<VecSimd<2>, 1>;
#if TECIDO_BATCH_X86
  if (width == 4) k = vf ? &lanes4::stages<lanes4::VecSimd<4>, 0> : &lanes4::stages<lanes4::VecSimd<4>, 1>;
  if (width == 8) k = vf ? &lanes8::stages<Avx512Simd, 0> : &lanes8::stages<Avx512Simd, 1>;
#endif
  k(x0, x1, stride, queries, n, cubic, verdict);
}

}  // namespace tecido
