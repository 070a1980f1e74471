#pragma once
/// The compile side of core's SIMD layer (core/simd/): which instruction sets this build can
/// target, and the macros that compile a region of code for one of them.
///
/// A kernel is written once as templates over a lane type (scalar_lanes.h, vec_lanes.inl,
/// avx512_lanes.h) in a kernel file without include guard, and for_each_width.inl includes
/// that file once per width, each copy in its own namespace, the wide copies between
/// TECIDO_SIMD_BEGIN_TARGET(isa) and TECIDO_SIMD_END_TARGET. So every function a wide kernel
/// calls carries the kernel's instruction set: a wide vector never crosses a call between
/// functions of different sets, which clang rejects (it checks the vector calling convention
/// before inlining) and GCC warns about. Only the region is compiled for the wider set, not
/// the translation unit: inline functions of the standard library or Eigen instantiated
/// elsewhere keep the baseline, so the linker can never pick an AVX copy for baseline code.
///
/// No multiply-add is ever fused: the build compiles with -ffp-contract=off (CMakeLists.txt),
/// which reaches these regions too (AVX-512F has FMA; GCC would contract a * b + c into it
/// under its default -ffp-contract=fast and change the last bit against the scalar code).
#if defined(__GNUC__) && defined(__x86_64__)
#define TECIDO_SIMD_X86 1
#define TECIDO_SIMD_PRAGMA(x) _Pragma(#x)
#if defined(__clang__)
#define TECIDO_SIMD_BEGIN_TARGET(isa) \
  TECIDO_SIMD_PRAGMA(clang attribute push(__attribute__((target(isa))), apply_to = function))
#define TECIDO_SIMD_END_TARGET _Pragma("clang attribute pop")
#else
#define TECIDO_SIMD_BEGIN_TARGET(isa) _Pragma("GCC push_options") TECIDO_SIMD_PRAGMA(GCC target(isa))
#define TECIDO_SIMD_END_TARGET _Pragma("GCC pop_options")
#endif
/// A function of one instruction set outside a target region (the AVX-512 lane type's members).
#define TECIDO_SIMD_TARGET_INLINE(isa) inline __attribute__((target(isa)))
#else
#define TECIDO_SIMD_X86 0
#endif

/// The lane operations are forced inline: a kernel is one function per width after inlining.
#define TECIDO_SIMD_INLINE inline __attribute__((always_inline))
