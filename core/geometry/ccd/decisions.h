#pragma once
/// The time search's arithmetic (decisions.inl) at width 1 of core's SIMD layer: the scalar
/// code of core's continuous collision test, the same text the batched stages compile at
/// widths 2, 4 and 8 (batch/stages.cpp).
#include "core/simd/scalar_lanes.h"

#include <cmath>

namespace tecido {
namespace ccd_scalar {

using Lanes = simd::ScalarLanes;
#include "core/simd/lane_math.inl"
#include "core/geometry/ccd/decisions.inl"

/// A row of three doubles as a 3-vector of width-1 lanes.
inline V3<Lanes> v3(const double* p) { return {p[0], p[1], p[2]}; }

}  // namespace ccd_scalar
}  // namespace tecido
