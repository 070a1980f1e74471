#pragma once
/// The `drift` suite's scenes: the conservative ones its invariants are measured on, and the cloths
/// it runs in core and in Bullet. Pure core scenes (no Bullet here).
#include "comparisons/suites/drift/settings.h"
#include "core/scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tecido::suites::drift {

/// A scene whose energy, momentum and angular momentum are invariants of the exact motion.
struct Conservative {
  std::string name;
  std::string about;  ///< one line for the report
  Scene scene;
};

/// "two-body-3d": two free particles (1 kg, 2 kg) on a spring (ks = 9 N/m, l = 1 m), stretched and
/// spinning, dt = 1e-3 s; "free-cloth": an unpinned 8 x 8 cloth (ks_B = 1 N/m, ks_A = 0.5 N/m,
/// 0.5 kg) with seeded random initial velocities (substream(seed, 42)), no gravity, dt = 2e-4 s.
/// No pins, no damping, no external force: only central internal forces.
std::vector<Conservative> conservative_scenes(std::uint64_t seed);

/// The twin comparison's cloth: twin_nodes^2 nodes, spacing twin_spacing, in the plane z = 0
/// from `origin`, mass twin_mass, type B springs twin_stiffness, gravity (0, 0, -9.81), step
/// twin_dt; pinned at (0, 0) and (0, n-1) when `pinned`.
Scene twin_cloth(const Settings& s, const Vec3& origin, bool pinned);

/// The twin's cloth, unpinned, released flat fall_height above a floor (a bounded plane z = 0,
/// 2 m x 2 m half extents, friction 0.5) with elasticity 0.
Scene falling_cloth(const Settings& s);

/// The classic comparison's curtain: classic_nodes^2 nodes over classic_side, hanging from its
/// pinned top row along -z from (0, 0, 1), mass classic_mass, type B springs classic_stiffness,
/// gravity, step classic_dt.
Scene classic_curtain(const Settings& s);

/// `scene` with every free particle's mass times `factor` (inverse masses divided by it).
Scene with_load(const Scene& scene, double factor);

/// A small cloth in wind with linear drag, for the not-modelled lists only.
Scene windy_cloth();

}  // namespace tecido::suites::drift
