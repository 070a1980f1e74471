#pragma once
/// Reads a scene file (docs/design.md section 3) into a core Scene, validating every value.
/// Keys (units SI; optional unless said):
///   integrator  "euler" | "symplectic" | "midpoint" | "rk4"   (default "symplectic", the seed's engine)
///   dt          step [s], required, 0 < dt <= 10
///   steps       number of steps, required, 0 <= steps <= 1e9 (and the work limit of `tecido run`)
///   seed        non-negative integer (default 0); drives random choices (a swirl's phase)
///   gravity     [gx,gy,gz] [m/s^2]; absent = no gravity
///   air_drag    linear drag coefficient c >= 0 [kg/s], force -c v; absent = none
///   wind        [fx,fy,fz] [N per particle], or {"force":[..], "swirl":{"rate":rad/s,
///               "axis":[..] (default [0,0,1]), "phase":rad (default: drawn from seed)},
///               "random":{"seed", "heading_diffusion":rad^2/s, "knot_interval":s} (with swirl;
///               core/dynamics/random_wind.h)}
///   particles   [{"position", "velocity" (default 0), "mass" (> 0, required unless pinned),
///                 "pinned" (default false), "elasticity" (k in [0,1], required when the scene has planes
///                 or an obstacle without its own elasticity)}]
///   springs     [{"i","j","stiffness" (>= 0),"rest_length" (>= 0, default: initial distance),"damping" (>= 0, default 0)}]
///   planes      [{"position","normal","forward","half_extents":[hx,hy] (>= 0),"friction" (in [0,1], default 0)}]
///   obstacles   [{"sphere"|"box"|"mesh": {...}, "friction", "elasticity", "velocity", "angular_velocity",
///                 "frames"}] (comparisons/io/obstacle_json.h)
///   edge_contacts  true | false (default false): springs against obstacle edges
///   contact     {"static_threshold","tangential_threshold","bisection_tolerance","max_events_per_step"}
///   cloth       {"rows","cols","spacing","origin","axis_u","axis_v","total_mass","stiffness_b",
///                "stiffness_a","damping","elasticity","pins":[[r,c],..]}; "elasticity" as for particles:
///                required when the scene has planes or an obstacle without its own elasticity
/// Keys starting with '_' are comments; any other unknown key is an error (a typo must not
/// silently remove a force). Sizes are bounded (comparisons/io/limits.h): particles (listed and
/// cloth nodes), springs (listed and the cloth's) and planes are counted before any is read.
#include "comparisons/io/json_reader.h"
#include "comparisons/io/limits.h"
#include "core/scene/scene.h"

#include <string>

namespace tecido::io {

/// Loads and validates a scene file; throws InputError (file, JSON pointer, problem).
Scene load_scene(const std::string& path);
/// Validates an already-parsed document; `file` names it in messages.
Scene scene_from_json(const Json& doc, const std::string& file);

}  // namespace tecido::io
