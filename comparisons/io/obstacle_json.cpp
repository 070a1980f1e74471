#include "comparisons/io/obstacle_json.h"

#include "comparisons/io/limits.h"
#include "comparisons/io/obj_mesh.h"
#include "comparisons/io/scene_json.h"
#include "core/geometry/obstacle_start.h"
#include "core/geometry/orient_predicates.h"

#include <filesystem>
#include <sstream>

namespace tecido::io {

namespace {

/// Keyframes of one mesh, and vertex positions over all its frames.
constexpr std::size_t kMaxMeshFrames = 100000;
constexpr std::size_t kMaxMeshFrameVertices = std::size_t{1} << 23;
constexpr double kMaxAngularSpeed = 1e6;  // [rad/s]

/// Reads the OBJ named at `where`, relative to the scene's folder; a file that cannot be read is
/// reported against the scene file and `where`, a bad line against the OBJ file and its line.
ObjMesh read_obj(const JsonReader& r, const Json& j, const std::string& where, const std::string& scene_file) {
  const std::string name = r.string(j, where);
  if (name.empty()) r.fail(where, "empty path");
  namespace fs = std::filesystem;
  const fs::path p = fs::path(name).is_absolute() ? fs::path(name) : fs::path(scene_file).parent_path() / name;
  ObjMesh mesh;
  try {
    mesh = load_obj_mesh(p.string());
  } catch (const InputError& e) {
    if (!e.where().empty()) throw;  // a line of the OBJ file
    r.fail(where, "cannot read \"" + p.string() + "\": " + e.problem());
  }
  if (mesh.vertices.size() > kMaxMeshVertices || mesh.triangles.size() > kMaxMeshTriangles)
    r.fail(where, "the mesh exceeds the limits of " + std::to_string(kMaxMeshVertices) + " vertices and " +
                      std::to_string(kMaxMeshTriangles) + " triangles");
  // The scene's coordinate limit holds for a mesh's vertices as for every other position (and keeps
  // the centroid's sum finite).
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (!(mesh.vertices[v].cwiseAbs().maxCoeff() <= kMaxCoordinate)) {
      std::ostringstream s;
      s << "coordinate " << mesh.vertices[v].cwiseAbs().maxCoeff() << " is out of range (|x| <= " << kMaxCoordinate << ")";
      throw InputError(p.string(), "vertex " + std::to_string(v + 1), s.str());
    }
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    // Collinear exactly when every axis-aligned projection is (exact orient2d signs).
    if (orient2d_sign(a.x(), a.y(), b.x(), b.y(), c.x(), c.y()) == 0 &&
        orient2d_sign(a.y(), a.z(), b.y(), b.z(), c.y(), c.z()) == 0 &&
        orient2d_sign(a.z(), a.x(), b.z(), b.x(), c.z(), c.x()) == 0)
      throw InputError(p.string(), "line " + std::to_string(mesh.triangle_line[f]),
                       "degenerate face: its corners are collinear (zero area)");
  }
  return mesh;
}

void read_sphere(const JsonReader& r, const Json& j, const std::string& w, Obstacle& o) {
  r.require_object(j, w);
  r.only_keys(j, w, {"center", "radius"});
  o.kind = ObstacleKind::Sphere;
  o.center = r.vec3(r.require(j, w, "center"), child(w, "center"), kMaxCoordinate);
  o.radius = r.number(r.require(j, w, "radius"), child(w, "radius"), kMaxCoordinate);
  if (!(o.radius > 0.0)) r.fail(child(w, "radius"), "radius must be > 0");
}

void read_box(const JsonReader& r, const Json& j, const std::string& w, Obstacle& o) {
  r.require_object(j, w);
  r.only_keys(j, w, {"center", "half_extents", "orientation"});
  o.kind = ObstacleKind::Box;
  o.center = r.vec3(r.require(j, w, "center"), child(w, "center"), kMaxCoordinate);
  const std::string wh = child(w, "half_extents");
  o.half_extents = r.vec3(r.require(j, w, "half_extents"), wh, kMaxCoordinate);
  for (int k = 0; k < 3; ++k)
    if (!(o.half_extents[k] > 0.0))
      r.fail(child(wh, static_cast<std::size_t>(k)), "half extent must be > 0 (a box without thickness has no inside)");
  if (!j.contains("orientation")) return;
  const std::string wo = child(w, "orientation");
  const Json& jo = r.require_object(j["orientation"], wo);
  r.only_keys(jo, wo, {"axis", "angle"});
  const Vec3 axis = r.vec3(r.require(jo, wo, "axis"), child(wo, "axis"));
  if (!(axis.norm() > 1e-12)) r.fail(child(wo, "axis"), "axis must not be zero");
  const double angle = r.number(r.require(jo, wo, "angle"), child(wo, "angle"), 1e6);
  o.orientation = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

void read_mesh(const JsonReader& r, const Json& j, const std::string& w, const std::string& scene_file, Obstacle& o) {
  r.require_object(j, w);
  r.only_keys(j, w, {"obj", "center"});
  o.kind = ObstacleKind::Mesh;
  const ObjMesh mesh = read_obj(r, r.require(j, w, "obj"), child(w, "obj"), scene_file);
  o.vertices = mesh.vertices;
  o.triangles = mesh.triangles;
  if (j.contains("center")) {
    o.center = r.vec3(j["center"], child(w, "center"), kMaxCoordinate);
  } else {
    o.center = Vec3::Zero();
    for (const Vec3& v : o.vertices) o.center += v;
    o.center /= static_cast<double>(o.vertices.size());
  }
}

void read_frames(const JsonReader& r, const Json& j, const std::string& w, const std::string& scene_file, Obstacle& o) {
  const Json& fs = r.require_array(j, w);
  if (fs.empty()) r.fail(w, "expected at least one frame");
  if (fs.size() > kMaxMeshFrames || fs.size() * o.vertices.size() > kMaxMeshFrameVertices)
    r.fail(w, "too many frames (at most " + std::to_string(kMaxMeshFrames) + ", and " +
                  std::to_string(kMaxMeshFrameVertices) + " vertex positions in all)");
  for (std::size_t k = 0; k < fs.size(); ++k) {
    const std::string wk = child(w, k);
    r.require_object(fs[k], wk);
    r.only_keys(fs[k], wk, {"time", "obj"});
    ObstacleMeshFrame frame;
    frame.time = r.number(r.require(fs[k], wk, "time"), child(wk, "time"), 1e12);
    if (k > 0 && !(frame.time > o.frames.back().time))
      r.fail(child(wk, "time"), "frame times must increase strictly (previous frame at " +
                                    std::to_string(o.frames.back().time) + " s)");
    const ObjMesh mesh = read_obj(r, r.require(fs[k], wk, "obj"), child(wk, "obj"), scene_file);
    if (mesh.vertices.size() != o.vertices.size())
      r.fail(child(wk, "obj"), "the frame has " + std::to_string(mesh.vertices.size()) + " vertices, the mesh " +
                                   std::to_string(o.vertices.size()));
    if (mesh.triangles != o.triangles) r.fail(child(wk, "obj"), "the frame's faces differ from the mesh's");
    frame.vertices = mesh.vertices;
    o.frames.push_back(std::move(frame));
  }
}

Obstacle read_obstacle(const JsonReader& r, const Json& j, const std::string& w, const std::string& scene_file) {
  r.require_object(j, w);
  r.only_keys(j, w, {"sphere", "box", "mesh", "friction", "elasticity", "velocity", "angular_velocity", "frames"});
  const int shapes = static_cast<int>(j.contains("sphere")) + j.contains("box") + j.contains("mesh");
  if (shapes != 1) r.fail(w, "an obstacle names exactly one of \"sphere\", \"box\", \"mesh\"");
  Obstacle o;
  if (j.contains("sphere")) read_sphere(r, j["sphere"], child(w, "sphere"), o);
  if (j.contains("box")) read_box(r, j["box"], child(w, "box"), o);
  if (j.contains("mesh")) read_mesh(r, j["mesh"], child(w, "mesh"), scene_file, o);
  if (j.contains("friction")) o.friction = r.number_in(j["friction"], child(w, "friction"), 0.0, 1.0);
  if (j.contains("elasticity")) o.elasticity = r.number_in(j["elasticity"], child(w, "elasticity"), 0.0, 1.0);
  if (j.contains("velocity")) o.velocity = r.vec3(j["velocity"], child(w, "velocity"), kMaxSpeed);
  if (j.contains("angular_velocity"))
    o.angular_velocity = r.vec3(j["angular_velocity"], child(w, "angular_velocity"), kMaxAngularSpeed);
  if (j.contains("frames")) {
    if (o.kind != ObstacleKind::Mesh) r.fail(child(w, "frames"), "frames move a mesh only");
    if (j.contains("velocity") || j.contains("angular_velocity"))
      r.fail(child(w, "frames"), "a mesh moves either by frames or by velocity and angular_velocity, not both");
    read_frames(r, j["frames"], child(w, "frames"), scene_file, o);
    o.vertices = o.frames.front().vertices;
  }
  return o;
}

}  // namespace

std::vector<Obstacle> read_obstacles(const JsonReader& r, const Json& j, const std::string& where,
                                     const std::string& scene_file) {
  const Json& list = r.require_array(j, where);
  if (list.size() > kMaxObstacles)
    r.fail(where, std::to_string(list.size()) + " obstacles exceed the limit of " + std::to_string(kMaxObstacles));
  std::vector<Obstacle> out;
  for (std::size_t k = 0; k < list.size(); ++k) out.push_back(read_obstacle(r, list[k], child(where, k), scene_file));
  return out;
}

bool obstacles_use_particle_k(const Json& obstacles) {
  if (!obstacles.is_array()) return false;
  for (const Json& o : obstacles)
    if (!o.is_object() || !o.contains("elasticity")) return true;
  return false;
}

void check_particles_outside(const JsonReader& r, const std::vector<Obstacle>& obstacles, const std::string& where,
                             const std::vector<Vec3>& x, const std::vector<std::uint8_t>& pinned) {
  for (std::size_t k = 0; k < obstacles.size(); ++k) {
    const int i = first_free_particle_inside(obstacles[k], x, pinned);
    if (i >= 0)
      r.fail(child(where, k), "free particle " + std::to_string(i) + " starts inside the " +
                                  obstacle_kind_name(obstacles[k].kind) + " (spheres and boxes are solid)");
  }
}

}  // namespace tecido::io
