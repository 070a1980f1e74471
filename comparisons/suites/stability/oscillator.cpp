#include "comparisons/suites/stability/oscillator.h"

#include "comparisons/suites/stability/theory.h"
#include "core/simulation/simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tecido::suites::stability {

StableStep find_max_stable_step(const std::function<bool(double)>& stable, double h_start, double rel_tol,
                                int max_doublings, int max_halvings) {
  StableStep r;
  auto test = [&](double h) {
    ++r.runs;
    return stable(h);
  };
  double lo = 0.0, hi = 0.0;
  if (test(h_start)) {
    lo = h_start;
    for (int k = 0; k < max_doublings && hi == 0.0; ++k) {
      const double h = 2.0 * lo;
      (test(h) ? lo : hi) = h;
    }
    if (hi == 0.0) {  // stable at every h tried: report the largest
      r.found = true;
      r.h = lo;
      return r;
    }
  } else {
    hi = h_start;
    for (int k = 0; k < max_halvings && lo == 0.0; ++k) {
      const double h = 0.5 * hi;
      (test(h) ? lo : hi) = h;
    }
    if (lo == 0.0) {  // unstable at every h tried
      r.h_unstable = hi;
      return r;
    }
  }
  while (hi - lo > rel_tol * lo) {
    const double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) break;
    (test(mid) ? lo : hi) = mid;
  }
  r.found = true;
  r.h = lo;
  r.h_unstable = hi;
  return r;
}

Scene oscillator_scene(IntegratorKind k, double ks, double m, double h) {
  Scene s;
  s.integrator = k;
  s.dt = h;
  s.particles.add(Vec3::Zero(), Vec3::Zero(), 0.0, 1.0, true);
  s.particles.add(Vec3(1.0, 0, 0), Vec3::Zero(), m, 1.0, false);
  s.forces.springs.push_back(Spring{0, 1, ks, 0.0, 0.0});
  return s;
}

long long steps_for(double periods, double omega, double h) {
  return static_cast<long long>(std::ceil(periods * 2.0 * kPi / (omega * h)));
}

OscillatorRun run_oscillator(IntegratorKind k, double ks, double m, double h, double periods, double amplitude_bound) {
  const double omega = std::sqrt(ks / m);
  Simulation sim(oscillator_scene(k, ks, m, h));
  OscillatorRun r;
  const long long n = steps_for(periods, omega, h);
  for (long long i = 0; i < n && r.finite && r.bounded; ++i) {
    r.steps = i + 1;
    r.finite = sim.step();
    r.bounded = !r.finite || sim.particles().x[1].norm() <= amplitude_bound;
  }
  if (!r.finite) {
    r.unstable_step = sim.instability()->step;
    r.growth_per_step = std::numeric_limits<double>::infinity();
    return r;
  }
  const Vec3& x = sim.particles().x[1];
  const Vec3& v = sim.particles().v[1];
  const double rn = std::sqrt(x.squaredNorm() + v.squaredNorm() / (omega * omega));
  const double r0 = 1.0;  // released at rest 1 m from the anchor
  r.growth_per_step = std::exp(std::log(rn / r0) / static_cast<double>(r.steps));
  return r;
}

StableStep oscillator_max_step(IntegratorKind k, double ks, double m, double periods, double amplitude_bound,
                               double rel_tol, int max_doublings, int max_halvings) {
  const double omega = std::sqrt(ks / m);
  return find_max_stable_step(
      [&](double h) {
        const OscillatorRun r = run_oscillator(k, ks, m, h, periods, amplitude_bound);
        return r.finite && r.bounded;
      },
      1.0 / omega, rel_tol, max_doublings, max_halvings);
}

BoundedRun run_bounded(const Scene& scene, long long n, const std::function<double(const Particles&)>& amp,
                       double limit) {
  Simulation sim(scene);
  BoundedRun r;
  for (long long i = 0; i < n; ++i) {
    r.steps = i + 1;
    if (!sim.step()) {
      r.finite = false;
      r.unstable_step = sim.instability()->step;
      return r;
    }
    const double a = amp(sim.particles());
    r.max_amp = std::max(r.max_amp, a);
    if (!(a <= limit)) {
      r.bounded = false;
      return r;
    }
  }
  return r;
}

}  // namespace tecido::suites::stability
