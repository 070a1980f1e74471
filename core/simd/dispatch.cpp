#include "core/simd/dispatch.h"

#include "core/platform/simd_level.h"
#include "core/simd/target.h"

namespace tecido {
namespace simd {

bool width_available(int width) {
  if (width == 1 || width == 2) return true;
#if TECIDO_SIMD_X86
  // The CPU has the set and TECIDO_SIMD allows it.
  if (width == 4) return simd_level_allowed(SimdLevel::AVX);
  if (width == 8) return simd_level_allowed(SimdLevel::AVX512);
#endif
  return false;
}

int widest_width(int floor, int ceiling) {
  for (int w = ceiling; w > floor; w /= 2)
    if (width_available(w)) return w;
  return floor;
}

}  // namespace simd
}  // namespace tecido
