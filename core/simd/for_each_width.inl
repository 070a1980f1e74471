/// Compiles one kernel file once per width of core's SIMD layer (core/simd/target.h), in the
/// manner of Highway's foreach_target.h: define TECIDO_SIMD_KERNEL as the kernel file's name,
/// then include this file inside the caller's (anonymous) namespace. It opens
///   simd1  width 1, ScalarLanes (the scalar code), baseline;
///   simd2  width 2, VecLanes<2> (SSE2, part of x86-64), baseline;
///   simd4  width 4, VecLanes<4>, compiled for AVX;
///   simd8  width 8, Avx512Lanes, compiled for AVX-512F;
/// each holding `Lanes`, `FloatLanes` (single precision in the same registers, float_lanes.h:
/// widths 1, 4, 4 and 16; 4 at simd4 too, as no 8-float type is needed yet), the small lane algebra (lane_math.inl) and the kernel's templates.
/// The AVX and AVX-512 copies exist on x86-64 with GCC or clang only (TECIDO_SIMD_X86);
/// dispatch.h picks one at run time. Define TECIDO_SIMD_NO_WIDTH1 first when the scalar copy
/// is not wanted.
// No include guard: meant to be included once per kernel file, inside a namespace, after
// core/simd/widths.h at file scope (its headers cannot be included inside a namespace).
#ifndef TECIDO_SIMD_WIDTHS_H
#error "include core/simd/widths.h at file scope first"
#endif
#ifndef TECIDO_SIMD_KERNEL
#error "define TECIDO_SIMD_KERNEL as the kernel file to include per width"
#endif

#ifndef TECIDO_SIMD_NO_WIDTH1
namespace simd1 {
using Lanes = ::tecido::simd::ScalarLanes;
using FloatLanes = ::tecido::simd::ScalarFloatLanes;
#include "core/simd/lane_math.inl"
#include TECIDO_SIMD_KERNEL
}  // namespace simd1
#endif
namespace simd2 {
#include "core/simd/vec_lanes.inl"
using Lanes = VecLanes<2>;
#if TECIDO_SIMD_X86
using FloatLanes = ::tecido::simd::Sse2FloatLanes;
#else
using FloatLanes = ::tecido::simd::ScalarFloatLanes;
#endif
#include "core/simd/lane_math.inl"
#include TECIDO_SIMD_KERNEL
}  // namespace simd2
#if TECIDO_SIMD_X86
TECIDO_SIMD_BEGIN_TARGET("avx")
namespace simd4 {
#include "core/simd/vec_lanes.inl"
using Lanes = VecLanes<4>;
using FloatLanes = ::tecido::simd::Sse2FloatLanes;
#include "core/simd/lane_math.inl"
#include TECIDO_SIMD_KERNEL
}  // namespace simd4
TECIDO_SIMD_END_TARGET
TECIDO_SIMD_BEGIN_TARGET("avx512f")
namespace simd8 {
using Lanes = ::tecido::simd::Avx512Lanes;
using FloatLanes = ::tecido::simd::Avx512FloatLanes;
#include "core/simd/lane_math.inl"
#include TECIDO_SIMD_KERNEL
}  // namespace simd8
TECIDO_SIMD_END_TARGET
#endif
#undef TECIDO_SIMD_KERNEL
#undef TECIDO_SIMD_NO_WIDTH1
