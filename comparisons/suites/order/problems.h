#pragma once
/// The `order` suite's analytic problems: scenes whose exact trajectories are known in closed
/// form, so the global error of any integrator can be measured against the truth.
#include "core/geometry/types.h"
#include "core/scene/scene.h"

#include <functional>
#include <string>
#include <vector>

namespace tecido::suites::order {

struct Problem {
  std::string name;
  std::string about;  ///< one line: the scene and its exact solution
  Scene scene;
  double T = 0.0;      ///< the error is measured at this time [s]
  double scale = 1.0;  ///< size of the solution [m]: the fit's round-off and instability thresholds scale with it
  std::function<std::vector<Vec3>(double t)> exact;  ///< every particle's exact position at t
};

/// x'' = -(k/m)(x - l): one spring (ks = 4 N/m, l = 1 m) to a pinned particle, m = 1 kg, released
/// 0.5 m stretched; x = 1 + 0.5 cos 2t.
Problem harmonic();
/// The same oscillator with linear drag c = 0.4 kg/s: x = 1 + e^{-gt}(A cos wd t + B sin wd t).
Problem damped();
/// m = 2 kg thrown at (3, 0, 5) m/s under gravity with linear drag c = 0.5 kg/s:
/// x = x0 + vinf t + (v0 - vinf)(m/c)(1 - e^{-ct/m}), vinf = m g / c.
Problem projectile_drag();
/// Two free particles (1 kg, 2 kg) on a spring (9 N/m, l = 1 m), oscillating along it while the
/// centre of mass drifts: separation l + (d0 - l) cos wt + (dv0/w) sin wt, w = sqrt(k/mu).
Problem two_body_spring();

/// The four, in report order.
std::vector<Problem> problems();

}  // namespace tecido::suites::order
