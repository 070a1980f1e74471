#pragma once
/// The widest SIMD instruction set core's run-time dispatch may use in this process.
///
/// Core's vector kernels (the spring forces of core/dynamics/packed_springs.h, the box tree's
/// node-pair masks of core/cloth/triangle_bvh.h) are compiled for baseline x86-64 and choose a
/// wider instruction set at run time from what the CPU supports. The environment variable
/// TECIDO_SIMD lowers that ceiling, so the figures of a CPU without AVX can be measured on one
/// with it (e.g. `TECIDO_SIMD=sse2 build/bin/tecido-bench --benchmark_filter=BM_ClothStep`):
///   unset or ""  the widest the CPU supports;
///   scalar       the spring loop without intrinsics (the box tree keeps its SSE2 compares,
///                which are part of x86-64);
///   sse2, avx, avx512   at most that instruction set (avx512 means AVX-512F).
/// A name the CPU (or this build) cannot run, or an unknown name, is refused: one line on
/// stderr and exit status 2, when the process starts. The variable is read once. Every kernel
/// produces the same bits (tests compare each with the plain loop), so the choice changes the
/// speed of a run, never its results.
#include <string>

namespace tecido {

/// Ordered: a level allows every level below it.
enum class SimdLevel { Scalar = 0, SSE2 = 1, AVX = 2, AVX512 = 3 };

/// "scalar", "sse2", "avx", "avx512": the names TECIDO_SIMD takes.
const char* simd_level_name(SimdLevel level);

/// Whether this build and this CPU can run `level` (x86-64 with GCC or Clang: SSE2 always, AVX
/// and AVX-512F by the CPU's feature flags; any other target: Scalar only).
bool cpu_has_simd_level(SimdLevel level);

/// The ceiling a TECIDO_SIMD value asks for; `error` is non-empty (one line) when the value is
/// refused: an unknown name, or a level cpu_has_simd_level() denies.
struct SimdChoice {
  SimdLevel level = SimdLevel::Scalar;
  std::string error;
};
/// `request` is the variable's value (nullptr or "": not set, the widest the CPU has).
SimdChoice choose_simd_level(const char* request);

/// This process's ceiling: choose_simd_level(getenv("TECIDO_SIMD")), read once (at start-up, by a
/// static initializer). A refused value prints its error on stderr and exits with status 2.
SimdLevel simd_level();

/// Whether a kernel of `level` may run in this process: the CPU has it and it is at most simd_level().
bool simd_level_allowed(SimdLevel level);

}  // namespace tecido
