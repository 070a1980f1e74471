#pragma once
/// The `obstacles` suite's analytic cases, one function per case group; each returns the case's
/// result as JSON (sweep.h: num() for doubles) for the suite to check against theory.h.
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/obstacles/settings.h"
#include "core/geometry/obstacle.h"

#include <limits>
#include <string>
#include <vector>

namespace tecido::suites::obstacles {

/// A value a case did not measure (it failed or does not apply): NaN.
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// How far x lies inside obstacle o at time t (its pose then, obstacle_pose.h): r - |x - c| for a
/// sphere, min_i (h_i - |q_i|) for a box; <= 0 outside or on the surface. 0 for a mesh (no inside).
double inside_depth(const Obstacle& o, double t, const Vec3& x);

/// A particle dropped from rest drop_height above a sphere's top (midpoint integrator):
/// {"t_exact", "t_core" (first logged contact), "apex_expected" (k^2 h), "apex_core" (the apex
/// implied by the first step end after the bounce, z + vz^2 / 2g, above the top: midpoint is exact
/// for constant acceleration), "apex_sampled" (highest step end after the bounce), "unstable"}.
io::Json sphere_drop_case(const Settings& s);

/// A particle sliding from rest down a box face tilted by slide_angle, friction slide_friction:
/// {"expected" (theory.h slide_distance), "distance" (along the slope), "max_offset" (largest
/// |distance from the face| over the run), "terminal_speed", "speed" (at the end)}.
io::Json slide_case(const Settings& s);

/// A particle left at rest on an obstacle's top for rest_steps steps ("sphere" or "box"):
/// {"max_offset" (largest |distance from the surface| at a step end), "max_depth" (deepest inside,
/// 0 if never), "max_speed", "resting" (still in resting contact at the end: 1 or 0)}.
io::Json rest_case(const Settings& s, const std::string& kind);

/// The fast-motion scenes: a particle at fast_speed against a thin box; a sphere and a box
/// translating at moving_speed through a particle at rest; a box spinning at spin_rate into one.
const std::vector<std::string>& fast_scene_names();

/// Fast scene `name` at step h for fast_run_steps steps: {"steps_inside" (step ends with the
/// particle strictly inside an obstacle, by inside_depth), "tunnelled" (step ends past the thin
/// box's far face; 0 for the others), "guard_corrections" (times core's end-of-step guard pushed
/// a particle out), "contacts", "unstable"}.
io::Json fast_case(const Settings& s, const std::string& name, double h);

}  // namespace tecido::suites::obstacles
