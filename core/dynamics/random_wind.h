#pragma once
/// The seed's random wind (section 3.1.2, fig. 15: the wind "behaves randomly, so that the
/// cloth does not come to rest inclined"; section 3.1.3, fig. 21: "a strong and constant wind
/// circling it constantly"). The seed gives no model; this one keeps what it does say:
///  - strong and constant: the magnitude |force| never changes (wind.h);
///  - circling: the heading turns about the axis at a mean rate (the swirl's `rate`);
///  - random: the heading also wanders, and the starting heading is not fixed.
/// Heading offset added to the swirl's angle rate * t + phase:
///   beta(t) = b_0 + W(t),  b_0 ~ Uniform[0, 2 pi),
///   W a random walk with W(0) = 0 and independent N(0, D tau) steps at the knots k tau,
///   linearly interpolated between knots (a Brownian heading of diffusion D [rad^2/s] seen at
///   resolution tau).
/// Knot k's step comes from a counter-based hash of (seed, k) (SplitMix64, Box-Muller), so
/// beta is a pure function of (seed, D, tau, t): the same at any step size, on any thread, in any
/// process; runs at different steps with the same seed see the same wind.
#include <cstdint>
#include <vector>

namespace tecido {

struct RandomHeading {
  std::uint64_t seed = 0;
  double diffusion = 0.0;      ///< D [rad^2/s]; 0 = no wander (only the random start b_0)
  double knot_interval = 0.1;  ///< tau [s], > 0 (the scene reader asks for [1e-3, 1e3])
  /// beta at knots 0..K (filled by prepare(); values beyond it are computed on the fly, equal
  /// bit for bit to a longer table).
  std::vector<double> knots;

  /// Fills `knots` up to time `horizon` [s] (at most 2^20 + 1 knots; later ones are computed when
  /// read, in time growing with their distance from the table's end).
  void prepare(double horizon);
  /// beta at knot k (k tau seconds).
  double knot(std::uint64_t k) const;
  /// beta(t) [rad], linear between knots; t < 0 (or not finite) reads as 0.
  double offset(double t) const;
};

/// The step of knot k >= 1 of a walk with this seed: sqrt(D tau) times a standard normal deviate.
double random_heading_step(std::uint64_t seed, double diffusion, double knot_interval, std::uint64_t k);

/// b_0: the starting heading offset of this seed, uniform in [0, 2 pi).
double random_heading_start(std::uint64_t seed);

}  // namespace tecido
