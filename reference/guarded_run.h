#pragma once
/// Running a reference engine for a fixed time and telling a blow-up from a result, for the
/// tradeoff suite's Bullet engines (bullet_deformable.h, bullet_softbody.h). Bullet zeroes NaN
/// velocity increments and clamps speeds, so a run that blew up stays finite: a node far from
/// its start is the sign. Header-only and Bullet-free.
#include "core/geometry/types.h"

#include <optional>
#include <vector>

namespace tecido::reference {

/// Steps `body` (body.step() -> false on failure; body.positions() -> node positions) `steps`
/// times. Nothing is returned when a step fails or a node is farther than `stray_limit` [m] from
/// its position in x0, checked every 64 steps (positions() copies, so not every step) and at the
/// end; otherwise the final positions.
template <class Body>
std::optional<std::vector<Vec3>> run_guarded(Body& body, const std::vector<Vec3>& x0, long long steps,
                                             double stray_limit) {
  const double limit2 = stray_limit * stray_limit;
  auto strayed = [&](const std::vector<Vec3>& x) {
    for (std::size_t k = 0; k < x.size(); ++k)
      if (!((x[k] - x0[k]).squaredNorm() <= limit2)) return true;
    return false;
  };
  for (long long i = 0; i < steps; ++i) {
    if (!body.step()) return std::nullopt;
    if ((i & 63) == 63 && strayed(body.positions())) return std::nullopt;
  }
  std::vector<Vec3> x = body.positions();
  if (strayed(x)) return std::nullopt;
  return x;
}

}  // namespace tecido::reference
