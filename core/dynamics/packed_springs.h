#pragma once
/// A spring list compiled for a fast force loop. Same law as spring.h (seed eq. 10, plus the
/// optional damping along the spring) and the same per-particle summation order as the plain
/// loop `accumulate_spring_forces` in force_model.h, so the two give bit-identical forces (on
/// targets without fused multiply-add contraction, e.g. x86-64; elsewhere they agree to
/// rounding). The one exception is the sign of a zero: a spring whose ends coincide (or whose
/// length is NaN) adds +0 here where the plain loop adds nothing.
///
/// Method. A cloth's springs come in families (cloth_builder.h): along one row of a family,
/// spring k joins particles i0 + k and i0 + k + offset. Consecutive springs of the list with
/// that pattern, and the same damped/undamped kind, form a run, stored as (i0, offset, count)
/// with the per-spring constants (stiffness, rest length, damping) in structure-of-arrays form.
/// The loop over a run therefore reads positions contiguously, loads no indices and has no
/// scatter, so it vectorizes. Each run is evaluated in blocks of kBlock springs, in two passes:
///   1. the force on the first end of each spring of the block, into a small SoA buffer;
///   2. subtract it from the second ends, then add it to the first ends (two stride-1 loops).
/// Summation order: within one run a particle is the first end of at most one spring and the
/// second end of at most one. When offset > 0 the spring of which it is the second end comes
/// earlier in the list, so pass 2 subtracts before it adds (offset < 0: adds first). Runs and
/// blocks are processed in list order. Every particle thus receives the same sequence of
/// additions as in the plain loop over the list. Runs shorter than kMinRun springs (an
/// arbitrary list from a scene file) take a scalar path with the plain loop's arithmetic.
///
/// Positions and velocities are copied into structure-of-arrays form once per evaluation, and
/// forces are accumulated into flat per-axis arrays (fx, fy, fz), which the caller reads.
///
/// Kernels. One sqrt and one division per spring bound pass 1; their throughput per
/// instruction hardly depends on the vector width (measured on the dev machine, an AMD EPYC:
/// 1.6 ns per sqrt + div with SSE2, 0.8 with AVX, 0.4 with AVX-512), so on x86-64 pass 1 is
/// written with intrinsics for SSE2 (2 springs per instruction, always present), AVX (4) and
/// AVX-512F (8); GCC would not vectorize std::sqrt itself without -fno-math-errno. A block's
/// last vector group overlaps the previous one instead of leaving a scalar tail (pass 1 only
/// writes the buffer, so redoing springs is harmless). Pass 2 is plain loops that the compiler
/// vectorizes with the same instruction set. The kernel is chosen at run time from what the CPU
/// supports (the build itself stays baseline x86-64: no -march flags, so Eigen's ABI is
/// untouched). All kernels perform the same IEEE operations lane-wise, with multiply-add
/// contraction disabled, so they produce the same bits; tests check each against the plain
/// loop.
#include "core/dynamics/spring.h"
#include "core/geometry/types.h"

#include <array>
#include <cstddef>
#include <vector>

namespace tecido {

/// The instruction sets a block can be evaluated with (x86-64: all, where the CPU has them;
/// elsewhere: Scalar only).
enum class SpringKernel { Scalar, SSE2, AVX, AVX512 };
const char* spring_kernel_name(SpringKernel k);
/// Whether this build and CPU can run kernel k and TECIDO_SIMD allows it (core/platform/simd_level.h).
bool spring_kernel_supported(SpringKernel k);
/// The widest supported kernel.
SpringKernel best_spring_kernel();

class PackedSprings {
 public:
  static constexpr int kBlock = 256;  ///< springs per pass-1 block (6 KB of force buffer)
  static constexpr int kMinRun = 4;   ///< shorter runs use the scalar path

  PackedSprings() = default;
  /// Compiles `springs` (kept in list order) for particles 0 .. max index.
  explicit PackedSprings(const std::vector<Spring>& springs);

  bool empty() const { return runs_.empty(); }
  std::size_t size() const { return stiffness_.size(); }
  /// Number of runs (diagnostics and tests: a rows x cols cloth gives about one per family row).
  std::size_t run_count() const { return runs_.size(); }
  /// The kernel in use (best_spring_kernel() unless set); set_kernel ignores an unsupported one.
  SpringKernel kernel() const { return kernel_; }
  void set_kernel(SpringKernel k) {
    if (spring_kernel_supported(k)) kernel_ = k;
  }

  /// Spring forces on particles at x with velocities v (v is read only by damped springs):
  /// afterwards fx()[i], fy()[i], fz()[i] hold the total spring force on particle i, for
  /// i < x.size(). Preconditions: every spring index < x.size(), v.size() == x.size().
  void accumulate(const std::vector<Vec3>& x, const std::vector<Vec3>& v);

  const double* fx() const { return fx_.data(); }
  const double* fy() const { return fy_.data(); }
  const double* fz() const { return fz_.data(); }

 private:
  struct Run {
    int first = 0;   // index of the run's first spring in the per-spring arrays
    int count = 0;   // springs in the run
    int i0 = 0;      // spring k of the run joins particles i0 + k and i0 + k + offset
    int offset = 0;
    bool damped = false;
  };
  void run_block(const Run& r, int k0, int m);
  void run_scalar(const Run& r, int k0, int m);

  std::vector<Run> runs_;
  std::vector<double> stiffness_, rest_length_, damping_;  // per spring, list order
  bool any_damped_ = false;
  SpringKernel kernel_ = best_spring_kernel();
  // Scratch, sized by accumulate().
  std::vector<double> x_, y_, z_, vx_, vy_, vz_, fx_, fy_, fz_;
  std::array<double, kBlock> bx_{}, by_{}, bz_{};
};

}  // namespace tecido
