#pragma once
/// Reads a scene's "obstacles" array into core Obstacles (docs/design.md section 3), validating
/// every value. Each entry holds exactly one shape and optional contact and motion keys:
///   {"sphere": {"center": [x,y,z], "radius": r > 0}}
///   {"box": {"center": [..], "half_extents": [hx,hy,hz] (each > 0),
///            "orientation": {"axis": [..] (not zero), "angle": radians} (default: axis-aligned)}}
///   {"mesh": {"obj": "path.obj" (relative to the scene file's folder), "center": [..] (the pivot
///             of "angular_velocity"; default: the centroid of the vertices)}}
///   "friction":   mu in [0, 1], as for planes (default 0, frictionless)
///   "elasticity": k in [0, 1] of contacts with this obstacle (default: each particle's own k)
///   "velocity":   [..] constant translation [m/s] (default 0)
///   "angular_velocity": [..] about the obstacle's centre, world frame [rad/s] (default 0)
///   "frames":     mesh only, instead of velocity and angular_velocity: [{"time": t, "obj": "..."}],
///                 times strictly increasing, every OBJ with the mesh's vertex count and faces;
///                 vertices move linearly between frames, hold before the first and after the last.
/// OBJ files are read by obj_mesh.h; a face whose corners are collinear (zero area, decided
/// exactly) is a degenerate face as well. Errors: io::InputError naming the scene file and the
/// JSON pointer, or the OBJ file and its line.
#include "comparisons/io/json_reader.h"
#include "core/geometry/obstacle.h"

#include <string>
#include <vector>

namespace tecido::io {

/// The obstacles of `j` (the value of "obstacles", at JSON pointer `where`); `scene_file` is the
/// scene's path, OBJ paths are relative to its folder.
std::vector<Obstacle> read_obstacles(const JsonReader& r, const Json& j, const std::string& where,
                                     const std::string& scene_file);

/// True when some obstacle entry has no "elasticity": then every free particle needs its own k.
bool obstacles_use_particle_k(const Json& obstacles);

/// Rejects a free particle that starts strictly inside a sphere or box (they are solid): the
/// message names the obstacle's pointer and the particle's index.
void check_particles_outside(const JsonReader& r, const std::vector<Obstacle>& obstacles, const std::string& where,
                             const std::vector<Vec3>& x, const std::vector<std::uint8_t>& pinned);

}  // namespace tecido::io
