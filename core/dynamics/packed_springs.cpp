#include "core/dynamics/packed_springs.h"

#include "core/platform/simd_level.h"

#include <algorithm>
#include <cmath>

#include "core/simd/widths.h"

namespace tecido {

static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 arrays are read as packed doubles");

const char* spring_kernel_name(SpringKernel k) {
  switch (k) {
    case SpringKernel::Scalar: return "scalar";
    case SpringKernel::SSE2: return "sse2";
    case SpringKernel::AVX: return "avx";
    case SpringKernel::AVX512: return "avx512";
  }
  return "?";
}

bool spring_kernel_supported(SpringKernel k) {
  // The CPU has it and TECIDO_SIMD allows it (core/platform/simd_level.h).
  switch (k) {
    case SpringKernel::Scalar: return true;
#if TECIDO_SIMD_X86
    case SpringKernel::SSE2: return simd_level_allowed(SimdLevel::SSE2);
    case SpringKernel::AVX: return simd_level_allowed(SimdLevel::AVX);
    case SpringKernel::AVX512: return simd_level_allowed(SimdLevel::AVX512);
#else
    default: return false;
#endif
  }
  return false;
}

SpringKernel best_spring_kernel() {
  for (SpringKernel k : {SpringKernel::AVX512, SpringKernel::AVX, SpringKernel::SSE2})
    if (spring_kernel_supported(k)) return k;
  return SpringKernel::Scalar;
}

namespace {

// One block of one run: spring k (0 <= k < m) joins first end a + k and second end b + k.
struct Block {
  const double *xa, *ya, *za, *xb, *yb, *zb;          // positions of the ends
  const double *vxa, *vya, *vza, *vxb, *vyb, *vzb;    // velocities (damped runs only)
  const double *ks, *ls, *cs;                         // stiffness, rest length, damping
  double *gx, *gy, *gz;                               // force on the first ends (pass 1 output)
  double *fxa, *fya, *fza, *fxb, *fyb, *fzb;          // accumulators at the ends
  int m;
  bool subtract_first;                                // offset > 0: second ends come earlier
};

// Pass 1 for springs k .. m-1, the reference form of every vector kernel below:
// f = (ks (len - l) [+ c (dv . d) / len]) / len * d, exactly the plain loop's operations in its
// order (force_model.cpp); a spring with len <= 0 or NaN contributes 0.
TECIDO_SIMD_INLINE void add_to(double* __restrict f, const double* __restrict g, int m) {
  for (int q = 0; q < m; ++q) f[q] += g[q];
}
TECIDO_SIMD_INLINE void subtract_from(double* __restrict f, const double* __restrict g, int m) {
  for (int q = 0; q < m; ++q) f[q] -= g[q];
}
TECIDO_SIMD_INLINE void pass2(const Block& p) {
  if (p.subtract_first) {
    subtract_from(p.fxb, p.gx, p.m);
    subtract_from(p.fyb, p.gy, p.m);
    subtract_from(p.fzb, p.gz, p.m);
  }
  add_to(p.fxa, p.gx, p.m);
  add_to(p.fya, p.gy, p.m);
  add_to(p.fza, p.gz, p.m);
  if (!p.subtract_first) {
    subtract_from(p.fxb, p.gx, p.m);
    subtract_from(p.fyb, p.gy, p.m);
    subtract_from(p.fzb, p.gz, p.m);
  }
}

// The block kernel, written once (spring_block.inl) and compiled per width (scalar, SSE2, AVX,
// AVX-512F); the build compiles with -ffp-contract=off (CMakeLists.txt), so no width fuses a
// multiply-add and every one rounds as the plain loop does.
#define TECIDO_SIMD_KERNEL "core/dynamics/spring_block.inl"
#include "core/simd/for_each_width.inl"

}  // namespace

PackedSprings::PackedSprings(const std::vector<Spring>& springs) {
  const std::size_t n = springs.size();
  stiffness_.reserve(n);
  rest_length_.reserve(n);
  damping_.reserve(n);
  for (std::size_t s = 0; s < n; ++s) {
    const Spring& sp = springs[s];
    const bool damped = sp.damping != 0.0;
    any_damped_ = any_damped_ || damped;
    stiffness_.push_back(sp.stiffness);
    rest_length_.push_back(sp.rest_length);
    damping_.push_back(sp.damping);
    // Extend the current run when this spring continues its pattern (next first end, same
    // offset, same kind); otherwise start a new run.
    if (!runs_.empty()) {
      Run& r = runs_.back();
      if (damped == r.damped && sp.i == r.i0 + r.count && sp.j - sp.i == r.offset) {
        ++r.count;
        continue;
      }
    }
    runs_.push_back(Run{static_cast<int>(s), 1, sp.i, sp.j - sp.i, damped});
  }
}

void PackedSprings::run_scalar(const Run& r, int k0, int m) {
  // The plain loop's arithmetic, one spring at a time (force_model.cpp).
  for (int k = k0; k < k0 + m; ++k) {
    const std::size_t s = static_cast<std::size_t>(r.first) + k;
    const std::size_t i = static_cast<std::size_t>(r.i0 + k);
    const std::size_t j = static_cast<std::size_t>(r.i0 + k + r.offset);
    const double dx = x_[j] - x_[i], dy = y_[j] - y_[i], dz = z_[j] - z_[i];
    const double len = std::sqrt((dx * dx + dy * dy) + dz * dz);
    if (!(len > 0.0)) continue;  // coincident ends: direction undefined, no force (eq. 10)
    const double inv_len = 1.0 / len;
    double mag = stiffness_[s] * (len - rest_length_[s]);
    if (r.damped) {
      const double dvx = vx_[j] - vx_[i], dvy = vy_[j] - vy_[i], dvz = vz_[j] - vz_[i];
      mag += damping_[s] * ((dvx * dx + dvy * dy) + dvz * dz) * inv_len;
    }
    const double c = mag * inv_len;
    const double gx = c * dx, gy = c * dy, gz = c * dz;
    fx_[i] += gx;
    fy_[i] += gy;
    fz_[i] += gz;
    fx_[j] -= gx;
    fy_[j] -= gy;
    fz_[j] -= gz;
  }
}

void PackedSprings::run_block(const Run& r, int k0, int m) {
  const std::ptrdiff_t a = static_cast<std::ptrdiff_t>(r.i0) + k0;  // first end of spring k0
  const std::ptrdiff_t b = a + r.offset;                              // its second end
  const std::size_t s0 = static_cast<std::size_t>(r.first) + k0;
  const bool v = r.damped;
  const Block p{x_.data() + a, y_.data() + a, z_.data() + a, x_.data() + b, y_.data() + b, z_.data() + b,
                v ? vx_.data() + a : nullptr, v ? vy_.data() + a : nullptr, v ? vz_.data() + a : nullptr,
                v ? vx_.data() + b : nullptr, v ? vy_.data() + b : nullptr, v ? vz_.data() + b : nullptr,
                stiffness_.data() + s0, rest_length_.data() + s0, damping_.data() + s0,
                bx_.data(), by_.data(), bz_.data(),
                fx_.data() + a, fy_.data() + a, fz_.data() + a, fx_.data() + b, fy_.data() + b, fz_.data() + b,
                m, r.offset > 0};
  switch (kernel_) {
#if TECIDO_SIMD_X86
    case SpringKernel::AVX512: return v ? simd8::block<simd8::Lanes, true>(p) : simd8::block<simd8::Lanes, false>(p);
    case SpringKernel::AVX: return v ? simd4::block<simd4::Lanes, true>(p) : simd4::block<simd4::Lanes, false>(p);
#endif
    case SpringKernel::SSE2: return v ? simd2::block<simd2::Lanes, true>(p) : simd2::block<simd2::Lanes, false>(p);
    default: return v ? simd1::block<simd1::Lanes, true>(p) : simd1::block<simd1::Lanes, false>(p);
  }
}

void PackedSprings::accumulate(const std::vector<Vec3>& x, const std::vector<Vec3>& v) {
  const std::size_t n = x.size();
  x_.resize(n);
  y_.resize(n);
  z_.resize(n);
  fx_.assign(n, 0.0);
  fy_.assign(n, 0.0);
  fz_.assign(n, 0.0);
  const double* px = x.empty() ? nullptr : x.front().data();
  for (std::size_t i = 0; i < n; ++i) {
    x_[i] = px[3 * i];
    y_[i] = px[3 * i + 1];
    z_[i] = px[3 * i + 2];
  }
  if (any_damped_) {
    vx_.resize(n);
    vy_.resize(n);
    vz_.resize(n);
    const double* pv = v.empty() ? nullptr : v.front().data();
    for (std::size_t i = 0; i < n; ++i) {
      vx_[i] = pv[3 * i];
      vy_[i] = pv[3 * i + 1];
      vz_[i] = pv[3 * i + 2];
    }
  }
  // Runs and blocks in list order (see the header).
  for (const Run& r : runs_) {
    if (r.count < kMinRun || r.offset == 0) {
      run_scalar(r, 0, r.count);
      continue;
    }
    for (int k0 = 0; k0 < r.count; k0 += kBlock) run_block(r, k0, std::min(kBlock, r.count - k0));
  }
}

}  // namespace tecido
