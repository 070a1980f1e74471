#pragma once
/// Everything for_each_width.inl needs at file scope: the lane types of every width and the
/// headers their operations use. Include it before including for_each_width.inl in a namespace.
#define TECIDO_SIMD_WIDTHS_H 1
#include "core/simd/avx512_lanes.h"
#include "core/simd/float_lanes.h"
#include "core/simd/scalar_lanes.h"
#include "core/simd/target.h"
#include "core/simd/vec_types.h"

#include <array>
#include <cfloat>
#include <initializer_list>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
