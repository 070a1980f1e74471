#pragma once
/// The scenes of the seed's cloth on a block (seed section 3.1.2, figs 10-13;
/// data/scenes/seed_fig10_12_block_121.json with 121 particles, seed_fig11_13_block_484.json with
/// 484, the choices the seed leaves open documented there) and of the cloth on a sphere
/// (data/scenes/cloth_on_sphere.json), as the suite runs them, and what the suite measures on them
/// relative to "up" (against gravity).
#include "comparisons/suites/obstacles/box_interior.h"
#include "comparisons/suites/obstacles/settings.h"
#include "core/scene/scene.h"

#include <array>
#include <string>
#include <vector>

namespace tecido::suites::obstacles {

/// The block scene with an n x n cloth (n one of block_sides) read from data_dir/scenes, with
/// edge contacts on or off. Throws std::invalid_argument for another n, io::InputError for a bad file.
Scene block_scene(const Settings& s, const std::string& data_dir, int n, bool edge_contacts);

/// The cloth-on-a-sphere scene read from data_dir/scenes.
Scene sphere_scene(const Settings& s, const std::string& data_dir);

/// Steps a block or sphere run takes: block_seconds / dt, or the scene's own steps when 0.
long long run_steps(const Settings& s, const Scene& scene);

/// The block of a block scene (its first obstacle) as an OrientedBox at t = 0 (it does not move).
OrientedBox block_of(const Scene& scene);

/// The (i, j) of every spring with a positive stiffness (the ones that hold the cloth together).
std::vector<std::array<int, 2>> stiff_springs(const Scene& scene);

/// Unit vector against gravity (+z without gravity).
Vec3 up_of(const Scene& scene);

/// Height of x above the box's top face along `up` (the face whose outward normal is nearest
/// `up`); `over` tells whether x lies within that face's outline.
double height_above_top(const OrientedBox& box, const Vec3& up, const Vec3& x, bool* over);

/// Where the block's four top edges fall against the cloth's grid at t = 0, in spacings: for each
/// edge (the box's side faces along its two horizontal axes, + then -), the distance from the edge
/// in to the nearest particle column on the top face's side, in [0, 1): 0 when a column lies on the
/// edge, 0.5 midway between columns. Two scenes with equal insets place the block alike against
/// their grids. Throws std::invalid_argument when the scene has no cloth or a horizontal axis of the
/// box is not parallel to one of the grid's axes.
std::array<double, 4> edge_insets(const Scene& scene);

/// The springs (stiff_springs) with exactly one end over the block's top face's outline at t = 0
/// (height_above_top's `over`): the springs that will cross the edge when the cloth drapes.
int springs_across_outline(const Scene& scene);

/// The smallest height of the cloth's particles above the obstacle's top at t = 0 (box: the top
/// face; sphere: its highest point): the fall before the first contact of a flat cloth.
double initial_gap(const Scene& scene);

}  // namespace tecido::suites::obstacles
