#pragma once
/// Outward rounding of a double to single precision: float_down(d) <= d <= float_up(d) for every
/// double d, so boxes rounded this way contain the double-precision boxes (broad phases that
/// store or compare boxes in single precision stay conservative: core/cloth/triangle_bvh.h,
/// core/cloth/continuous_self_collision.h).
///
/// Method, without branches: (float)d is within half an ulp of d; moving it away by
/// |f| 2^-23 + 2^-126 (at least one ulp of f, and at least the smallest normal float) gives a
/// float on the far side of d, whatever the rounding of the subtraction itself (the exact
/// result lies at least one ulp beyond f, and f +- ulp is representable). Everything is clamped
/// to [-FLT_MAX, FLT_MAX]: clamping is monotone, so two intervals that overlap still overlap
/// after it, and a value beyond the float range maps to a bound still beyond it on the outer
/// side (float_up(d) >= d for d < -FLT_MAX, float_down(d) <= d for d > FLT_MAX), the boxes stay
/// finite, and the empty lanes' inverted infinite boxes (lo = +inf, hi = -inf) can never
/// overlap one. Both are monotone (non-decreasing) in d.
#include <algorithm>
#include <cfloat>
#include <cmath>

namespace tecido {

inline float float_down(double d) {
  constexpr double kFloatMax = FLT_MAX;
  const float f = static_cast<float>(std::min(std::max(d, -kFloatMax), kFloatMax));
  return std::max(f - (std::fabs(f) * 0x1p-23f + FLT_MIN), -FLT_MAX);
}

inline float float_up(double d) {
  constexpr double kFloatMax = FLT_MAX;
  const float f = static_cast<float>(std::min(std::max(d, -kFloatMax), kFloatMax));
  return std::min(f + (std::fabs(f) * 0x1p-23f + FLT_MIN), FLT_MAX);
}

}  // namespace tecido
