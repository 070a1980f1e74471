#pragma once
/// The seed's cloth-on-a-block scene (seed section 3.1.2, figs 10-13) as the suite builds it: a
/// square cloth of n x n particles (11: fig. 10's 121, 22: fig. 11's 484) dropped flat onto a cube
/// whose top is at z = 0, with or without edge contacts; the cloth, block and step from
/// settings.h. The seed leaves the sizes open; the choices are printed in the report.
#include "comparisons/suites/obstacles/box_interior.h"
#include "comparisons/suites/obstacles/settings.h"
#include "core/scene/scene.h"

#include <array>
#include <vector>

namespace tecido::suites::obstacles {

/// The block scene with an n x n cloth.
Scene block_scene(const Settings& s, int n, bool edge_contacts);

/// The block of a block scene (its first obstacle) as an OrientedBox at t = 0 (it does not move).
OrientedBox block_of(const Scene& scene);

/// The (i, j) of every spring with a positive stiffness (the ones that hold the cloth together).
std::vector<std::array<int, 2>> stiff_springs(const Scene& scene);

}  // namespace tecido::suites::obstacles

namespace tecido::suites::obstacles {

/// The same cloth (n x n) dropped onto a sphere of sphere_radius whose top is at z = 0 (the
/// cloth-on-a-sphere scene; friction block_friction).
Scene sphere_scene(const Settings& s, int n);

}  // namespace tecido::suites::obstacles
