#include "core/dynamics/packed_springs.h"

#include "core/platform/simd_level.h"

#include <algorithm>
#include <cmath>

#if defined(__GNUC__) && defined(__x86_64__)
#define TECIDO_SPRING_X86 1
#include <immintrin.h>
// AVX has no fused multiply-add; AVX-512F does, and GCC would contract a*b + c in such a
// function (-ffp-contract=fast is its default), changing the rounding: switch it off there.
// (Clang's default only fuses within one source expression, never across intrinsic calls.)
#if defined(__clang__)
#define TECIDO_TARGET_AVX __attribute__((target("avx")))
#define TECIDO_TARGET_AVX512 __attribute__((target("avx512f")))
#else
#define TECIDO_TARGET_AVX __attribute__((target("avx")))
#define TECIDO_TARGET_AVX512 __attribute__((target("avx512f"), optimize("fp-contract=off")))
#endif
#define TECIDO_INLINE inline __attribute__((always_inline))
#else
#define TECIDO_SPRING_X86 0
#define TECIDO_INLINE inline
#endif

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
#if TECIDO_SPRING_X86
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
template <bool Damped>
TECIDO_INLINE void pass1_scalar(const Block& p, int k) {
  for (; k < p.m; ++k) {
    const double dx = p.xb[k] - p.xa[k], dy = p.yb[k] - p.ya[k], dz = p.zb[k] - p.za[k];
    const double len = std::sqrt((dx * dx + dy * dy) + dz * dz);
    const double inv_len = 1.0 / len;
    double mag = p.ks[k] * (len - p.ls[k]);
    if constexpr (Damped) {
      const double dvx = p.vxb[k] - p.vxa[k], dvy = p.vyb[k] - p.vya[k], dvz = p.vzb[k] - p.vza[k];
      mag += p.cs[k] * ((dvx * dx + dvy * dy) + dvz * dz) * inv_len;
    }
    const double c = mag * inv_len;
    const bool ok = len > 0.0;
    p.gx[k] = ok ? c * dx : 0.0;
    p.gy[k] = ok ? c * dy : 0.0;
    p.gz[k] = ok ? c * dz : 0.0;
  }
}

// Pass 2: scatter in the plain loop's per-particle order (see the header). Stride-1 loops
// over distinct arrays, so the compiler vectorizes them (with the caller's instruction set).
TECIDO_INLINE void add_to(double* __restrict f, const double* __restrict g, int m) {
  for (int q = 0; q < m; ++q) f[q] += g[q];
}
TECIDO_INLINE void subtract_from(double* __restrict f, const double* __restrict g, int m) {
  for (int q = 0; q < m; ++q) f[q] -= g[q];
}
TECIDO_INLINE void pass2(const Block& p) {
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

template <bool Damped>
void block_scalar(const Block& p) {
  pass1_scalar<Damped>(p, 0);
  pass2(p);
}

#if TECIDO_SPRING_X86
// pass1_scalar, two springs per instruction. Written out because GCC does not vectorize
// std::sqrt without -fno-math-errno.
template <bool Damped>
void block_sse2(const Block& block) {
  const Block p = block;  // local copy: no store below can alias it, so its pointers stay in registers
  const __m128d zero = _mm_setzero_pd(), one = _mm_set1_pd(1.0);
  // Groups of 2 springs from k = 0; pass 1 is pure, so the last group may overlap the one
  // before it (it rewrites the same values) instead of leaving a scalar tail.
  if (p.m >= 2) {
    for (int k = 0;; k = std::min(k + 2, p.m - 2)) {
      const __m128d dx = _mm_sub_pd(_mm_loadu_pd(p.xb + k), _mm_loadu_pd(p.xa + k));
      const __m128d dy = _mm_sub_pd(_mm_loadu_pd(p.yb + k), _mm_loadu_pd(p.ya + k));
      const __m128d dz = _mm_sub_pd(_mm_loadu_pd(p.zb + k), _mm_loadu_pd(p.za + k));
      const __m128d len = _mm_sqrt_pd(_mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy)), _mm_mul_pd(dz, dz)));
      const __m128d inv_len = _mm_div_pd(one, len);
      __m128d mag = _mm_mul_pd(_mm_loadu_pd(p.ks + k), _mm_sub_pd(len, _mm_loadu_pd(p.ls + k)));
      if constexpr (Damped) {
        const __m128d dvx = _mm_sub_pd(_mm_loadu_pd(p.vxb + k), _mm_loadu_pd(p.vxa + k));
        const __m128d dvy = _mm_sub_pd(_mm_loadu_pd(p.vyb + k), _mm_loadu_pd(p.vya + k));
        const __m128d dvz = _mm_sub_pd(_mm_loadu_pd(p.vzb + k), _mm_loadu_pd(p.vza + k));
        const __m128d dot = _mm_add_pd(_mm_add_pd(_mm_mul_pd(dvx, dx), _mm_mul_pd(dvy, dy)), _mm_mul_pd(dvz, dz));
        mag = _mm_add_pd(mag, _mm_mul_pd(_mm_mul_pd(_mm_loadu_pd(p.cs + k), dot), inv_len));
      }
      const __m128d c = _mm_mul_pd(mag, inv_len);
      const __m128d ok = _mm_cmpgt_pd(len, zero);  // all ones where len > 0; zero otherwise and for NaN
      _mm_storeu_pd(p.gx + k, _mm_and_pd(ok, _mm_mul_pd(c, dx)));
      _mm_storeu_pd(p.gy + k, _mm_and_pd(ok, _mm_mul_pd(c, dy)));
      _mm_storeu_pd(p.gz + k, _mm_and_pd(ok, _mm_mul_pd(c, dz)));
      if (k + 2 == p.m) break;
    }
  } else {
    pass1_scalar<Damped>(p, 0);
  }
  pass2(p);
}

// The same, four springs per instruction.
template <bool Damped>
TECIDO_TARGET_AVX void block_avx(const Block& block) {
  const Block p = block;  // local copy: no store below can alias it, so its pointers stay in registers
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
  // Groups of 4 springs from k = 0; pass 1 is pure, so the last group may overlap the one
  // before it (it rewrites the same values) instead of leaving a scalar tail.
  if (p.m >= 4) {
    for (int k = 0;; k = std::min(k + 4, p.m - 4)) {
      const __m256d dx = _mm256_sub_pd(_mm256_loadu_pd(p.xb + k), _mm256_loadu_pd(p.xa + k));
      const __m256d dy = _mm256_sub_pd(_mm256_loadu_pd(p.yb + k), _mm256_loadu_pd(p.ya + k));
      const __m256d dz = _mm256_sub_pd(_mm256_loadu_pd(p.zb + k), _mm256_loadu_pd(p.za + k));
      const __m256d len =
          _mm256_sqrt_pd(_mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz)));
      const __m256d inv_len = _mm256_div_pd(one, len);
      __m256d mag = _mm256_mul_pd(_mm256_loadu_pd(p.ks + k), _mm256_sub_pd(len, _mm256_loadu_pd(p.ls + k)));
      if constexpr (Damped) {
        const __m256d dvx = _mm256_sub_pd(_mm256_loadu_pd(p.vxb + k), _mm256_loadu_pd(p.vxa + k));
        const __m256d dvy = _mm256_sub_pd(_mm256_loadu_pd(p.vyb + k), _mm256_loadu_pd(p.vya + k));
        const __m256d dvz = _mm256_sub_pd(_mm256_loadu_pd(p.vzb + k), _mm256_loadu_pd(p.vza + k));
        const __m256d dot =
            _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dvx, dx), _mm256_mul_pd(dvy, dy)), _mm256_mul_pd(dvz, dz));
        mag = _mm256_add_pd(mag, _mm256_mul_pd(_mm256_mul_pd(_mm256_loadu_pd(p.cs + k), dot), inv_len));
      }
      const __m256d c = _mm256_mul_pd(mag, inv_len);
      const __m256d ok = _mm256_cmp_pd(len, zero, _CMP_GT_OQ);
      _mm256_storeu_pd(p.gx + k, _mm256_and_pd(ok, _mm256_mul_pd(c, dx)));
      _mm256_storeu_pd(p.gy + k, _mm256_and_pd(ok, _mm256_mul_pd(c, dy)));
      _mm256_storeu_pd(p.gz + k, _mm256_and_pd(ok, _mm256_mul_pd(c, dz)));
      if (k + 4 == p.m) break;
    }
  } else {
    pass1_scalar<Damped>(p, 0);
  }
  pass2(p);
}

// The same, eight springs per instruction (lanes with len <= 0 or NaN are zeroed by the mask).
// GCC 12 warns falsely about _mm512_undefined_pd inside _mm512_sqrt_pd (-Wmaybe-uninitialized).
#if !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
template <bool Damped>
TECIDO_TARGET_AVX512 void block_avx512(const Block& block) {
  const Block p = block;  // local copy: no store below can alias it, so its pointers stay in registers
  const __m512d zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1.0);
  // Groups of 8 springs from k = 0; pass 1 is pure, so the last group may overlap the one
  // before it (it rewrites the same values) instead of leaving a scalar tail.
  if (p.m >= 8) {
    for (int k = 0;; k = std::min(k + 8, p.m - 8)) {
      const __m512d dx = _mm512_sub_pd(_mm512_loadu_pd(p.xb + k), _mm512_loadu_pd(p.xa + k));
      const __m512d dy = _mm512_sub_pd(_mm512_loadu_pd(p.yb + k), _mm512_loadu_pd(p.ya + k));
      const __m512d dz = _mm512_sub_pd(_mm512_loadu_pd(p.zb + k), _mm512_loadu_pd(p.za + k));
      const __m512d len =
          _mm512_sqrt_pd(_mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy)), _mm512_mul_pd(dz, dz)));
      const __m512d inv_len = _mm512_div_pd(one, len);
      __m512d mag = _mm512_mul_pd(_mm512_loadu_pd(p.ks + k), _mm512_sub_pd(len, _mm512_loadu_pd(p.ls + k)));
      if constexpr (Damped) {
        const __m512d dvx = _mm512_sub_pd(_mm512_loadu_pd(p.vxb + k), _mm512_loadu_pd(p.vxa + k));
        const __m512d dvy = _mm512_sub_pd(_mm512_loadu_pd(p.vyb + k), _mm512_loadu_pd(p.vya + k));
        const __m512d dvz = _mm512_sub_pd(_mm512_loadu_pd(p.vzb + k), _mm512_loadu_pd(p.vza + k));
        const __m512d dot =
            _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(dvx, dx), _mm512_mul_pd(dvy, dy)), _mm512_mul_pd(dvz, dz));
        mag = _mm512_add_pd(mag, _mm512_mul_pd(_mm512_mul_pd(_mm512_loadu_pd(p.cs + k), dot), inv_len));
      }
      const __m512d c = _mm512_mul_pd(mag, inv_len);
      const __mmask8 ok = _mm512_cmp_pd_mask(len, zero, _CMP_GT_OQ);
      _mm512_storeu_pd(p.gx + k, _mm512_maskz_mul_pd(ok, c, dx));
      _mm512_storeu_pd(p.gy + k, _mm512_maskz_mul_pd(ok, c, dy));
      _mm512_storeu_pd(p.gz + k, _mm512_maskz_mul_pd(ok, c, dz));
      if (k + 8 == p.m) break;
    }
  } else {
    pass1_scalar<Damped>(p, 0);
  }
  pass2(p);
}
#if !defined(__clang__)
#pragma GCC diagnostic pop
#endif
#endif

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
#if TECIDO_SPRING_X86
    case SpringKernel::AVX512: return v ? block_avx512<true>(p) : block_avx512<false>(p);
    case SpringKernel::AVX: return v ? block_avx<true>(p) : block_avx<false>(p);
    case SpringKernel::SSE2: return v ? block_sse2<true>(p) : block_sse2<false>(p);
#endif
    default: return v ? block_scalar<true>(p) : block_scalar<false>(p);
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
