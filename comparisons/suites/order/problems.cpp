#include "comparisons/suites/order/problems.h"

#include <cmath>

namespace tecido::suites::order {

namespace {
/// A particle of mass m on a spring (k, l) to a pinned particle at the origin, released at x0.
Scene pinned_spring(double m, double k, double l, double x0) {
  Scene s;
  s.particles.add(Vec3::Zero(), Vec3::Zero(), 0.0, 1.0, true);
  s.particles.add(Vec3(x0, 0, 0), Vec3::Zero(), m, 1.0, false);
  s.forces.springs.push_back(Spring{0, 1, k, l, 0.0});
  return s;
}
}  // namespace

Problem harmonic() {
  Problem p{"harmonic", "one spring (ks = 4 N/m, l = 1 m) to a pinned particle, m = 1 kg, released 0.5 m stretched: x = 1 + 0.5 cos 2t",
            pinned_spring(1.0, 4.0, 1.0, 1.5), 4.0, 1.0, {}};
  p.exact = [](double t) { return std::vector<Vec3>{Vec3::Zero(), Vec3(1.0 + 0.5 * std::cos(2.0 * t), 0, 0)}; };
  return p;
}

Problem damped() {
  const double m = 1.0, k = 4.0, c = 0.4, A = 0.5;
  const double g = c / (2 * m), wd = std::sqrt(k / m - g * g), B = g * A / wd;
  Problem p{"damped", "the same oscillator with linear air drag c = 0.4 kg/s (underdamped, gamma = 0.2 1/s)",
            pinned_spring(m, k, 1.0, 1.5), 4.0, 1.0, {}};
  p.scene.forces.air_drag = c;
  p.exact = [=](double t) {
    return std::vector<Vec3>{Vec3::Zero(), Vec3(1.0 + std::exp(-g * t) * (A * std::cos(wd * t) + B * std::sin(wd * t)), 0, 0)};
  };
  return p;
}

Problem projectile_drag() {
  const double m = 2.0, c = 0.5;
  const Vec3 g(0, 0, -9.81), v0(3, 0, 5), x0(0, 0, 0);
  const Vec3 vinf = m * g / c;
  Problem p{"projectile-drag", "m = 2 kg thrown at (3, 0, 5) m/s under gravity with linear drag c = 0.5 kg/s", {}, 4.0, 10.0, {}};
  p.scene.particles.add(x0, v0, m, 1.0, false);
  p.scene.forces.gravity = g;
  p.scene.forces.air_drag = c;
  p.exact = [=](double t) { return std::vector<Vec3>{x0 + vinf * t + (v0 - vinf) * (m / c) * (1.0 - std::exp(-c * t / m))}; };
  return p;
}

Problem two_body_spring() {
  const double m1 = 1.0, m2 = 2.0, k = 9.0, l = 1.0;
  const double M = m1 + m2, mu = m1 * m2 / M, w = std::sqrt(k / mu);
  const Vec3 x1(0, 0, 0), x2(1.2, 0, 0), v1(0.5, 0, 0), v2(-0.1, 0, 0);
  const Vec3 X0 = (m1 * x1 + m2 * x2) / M, V = (m1 * v1 + m2 * v2) / M;
  const double d0 = 1.2, dv0 = v2.x() - v1.x();
  Problem p{"two-body-spring",
            "m1 = 1 kg and m2 = 2 kg joined by ks = 9 N/m, l = 1 m, oscillating along the spring while the centre of mass drifts",
            {}, 4.0, 1.0, {}};
  p.scene.particles.add(x1, v1, m1, 1.0, false);
  p.scene.particles.add(x2, v2, m2, 1.0, false);
  p.scene.forces.springs.push_back(Spring{0, 1, k, l, 0.0});
  p.exact = [=](double t) {
    const double d = l + (d0 - l) * std::cos(w * t) + dv0 / w * std::sin(w * t);
    const Vec3 X = X0 + V * t;
    return std::vector<Vec3>{X - Vec3(m2 / M * d, 0, 0), X + Vec3(m1 / M * d, 0, 0)};
  };
  return p;
}

std::vector<Problem> problems() { return {harmonic(), damped(), projectile_drag(), two_body_spring()}; }

}  // namespace tecido::suites::order
