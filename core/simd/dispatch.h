#pragma once
/// The run-time side of core's SIMD layer: which widths this process may run (the CPU's
/// instruction sets under the TECIDO_SIMD ceiling, core/platform/simd_level.h) and the choice
/// of a kernel's copy for a width (the copies for_each_width.inl compiles).
///
/// Widths and the level each needs: 1 scalar (always), 2 SSE2 (always on x86-64; elsewhere the
/// GCC vector types lower to scalar code, still bit-identical), 4 AVX, 8 AVX-512F.

namespace tecido {
namespace simd {

/// Whether a kernel of `width` (1, 2, 4 or 8) may run in this process.
bool width_available(int width);

/// The widest available width no wider than `ceiling`, at least `floor` (which must itself be
/// available: 1 or 2).
int widest_width(int floor = 2, int ceiling = 8);

/// The kernel of `width` among the four copies (nullptr where a copy is not compiled, e.g.
/// off x86-64; the caller asks only for available widths).
template <class Fn>
Fn pick(int width, Fn w1, Fn w2, Fn w4, Fn w8) {
  switch (width) {
    case 1: return w1;
    case 4: return w4;
    case 8: return w8;
    default: return w2;
  }
}

}  // namespace simd
}  // namespace tecido
