#include "core/dynamics/random_wind.h"

#include <cmath>

namespace tecido {

namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr double kMaxTableKnots = 1 << 20;  // 8 MB; later knots are computed on the fly

/// SplitMix64's output function (Steele, Lea, Flood 2014) of `z`: a well-mixed 64-bit value.
std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

/// The n-th value of the stream `seed`: SplitMix64 at counter n.
std::uint64_t draw(std::uint64_t seed, std::uint64_t n) { return mix(seed + 0x9E3779B97F4A7C15ULL * (n + 1)); }

/// Uniform in [0, 1) with 53 random bits.
double unit(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

}  // namespace

double random_heading_start(std::uint64_t seed) { return kTwoPi * unit(draw(seed, 0)); }

double random_heading_step(std::uint64_t seed, double diffusion, double knot_interval, std::uint64_t k) {
  if (diffusion == 0.0) return 0.0;
  // Box-Muller on two uniforms of this knot: u1 in (0, 1], u2 in [0, 1).
  const double u1 = 1.0 - unit(draw(seed, 2 * k));
  const double u2 = unit(draw(seed, 2 * k + 1));
  const double z = std::sqrt(-2.0 * std::log(u1)) * std::cos(kTwoPi * u2);
  return std::sqrt(diffusion * knot_interval) * z;
}

void RandomHeading::prepare(double horizon) {
  const double h = horizon > 0.0 ? horizon : 0.0;
  double n = std::ceil(h / knot_interval) + 1.0;
  if (!(n <= kMaxTableKnots)) n = kMaxTableKnots;  // also NaN
  const auto last = static_cast<std::uint64_t>(n);
  knots.clear();
  knots.reserve(last + 1);
  knots.push_back(random_heading_start(seed));
  for (std::uint64_t k = 1; k <= last; ++k)
    knots.push_back(knots.back() + random_heading_step(seed, diffusion, knot_interval, k));
}

double RandomHeading::knot(std::uint64_t k) const {
  if (k < knots.size()) return knots[k];
  // Past the table: continue its sums in the same order, so the value equals a longer table's.
  std::uint64_t j = knots.empty() ? 0 : knots.size() - 1;
  double b = knots.empty() ? random_heading_start(seed) : knots.back();
  for (++j; j <= k; ++j) b += random_heading_step(seed, diffusion, knot_interval, j);
  return b;
}

double RandomHeading::offset(double t) const {
  const double s = (t > 0.0 && std::isfinite(t)) ? t / knot_interval : 0.0;
  const double fk = std::floor(s);
  const auto k = static_cast<std::uint64_t>(fk);
  const double b0 = knot(k);
  return b0 + (s - fk) * (knot(k + 1) - b0);
}

}  // namespace tecido
