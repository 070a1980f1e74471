// libFuzzer target: a scene's "obstacles" array (io::read_obstacles, comparisons/io/obstacle_json.h)
// with the OBJ files its meshes and keyframes name. The input is split at each line "%%%\n":
// the first part is the JSON value of "obstacles", the next ones are the files 0.obj, 1.obj, ...
// written into a per-process folder beside the scene file (paths relative to the scene, as
// `tecido run` resolves them). Rejections must be io::InputError; anything else is a finding,
// and so is an accepted obstacle that breaks what the reader promises: at most io::kMaxObstacles,
// finite centres within io::kMaxCoordinate, a sphere radius > 0, box half extents > 0 and an
// orthonormal orientation, friction and elasticity in [0, 1], a velocity within io::kMaxSpeed,
// a mesh within the mesh limits with indices in range and no face repeating a corner, keyframe
// times strictly increasing with every frame's vertex count the mesh's. Accepted obstacles then
// go through check_particles_outside on a few particles (again InputError or nothing).
// A mesh's OBJ coordinates were found to be checked for finiteness only (a mesh at 3e16 m accepted,
// coordinates near 1e308 overflowing the centroid; regress_mesh_beyond_coordinate_limit): the
// reader now holds them to io::kMaxCoordinate, and so does this target.
#include "fuzz_common.h"

#include "comparisons/io/obstacle_json.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace {

constexpr const char* kTarget = "fuzz_obstacles";
namespace io = tecido::io;
using tecido::fuzz::finding;

const std::string& folder() {
  static const std::string dir = [] {
    const std::string d = "/tmp/tecido_fuzz_obstacles." + std::to_string(::getpid());
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

/// Writes the OBJ parts (removing those of the previous input, so that every input is read alone);
/// returns the JSON part.
std::string split_and_write(const std::string& text) {
  for (int k = 0; k < 8; ++k) std::filesystem::remove(folder() + "/" + std::to_string(k) + ".obj");
  const std::string sep = "%%%\n";
  std::size_t at = text.find(sep);
  const std::string json = text.substr(0, at);
  for (int k = 0; at != std::string::npos && k < 8; ++k) {
    const std::size_t from = at + sep.size();
    at = text.find(sep, from);
    std::ofstream(folder() + "/" + std::to_string(k) + ".obj", std::ios::binary | std::ios::trunc)
        << text.substr(from, at == std::string::npos ? std::string::npos : at - from);
  }
  return json;
}

bool within(const tecido::Vec3& v, double limit) { return v.allFinite() && v.cwiseAbs().maxCoeff() <= limit; }

void check_mesh(const tecido::Obstacle& o, const std::string& k) {
  if (o.vertices.size() > io::kMaxMeshVertices || o.triangles.size() > io::kMaxMeshTriangles || o.triangles.empty())
    finding(kTarget, "obstacle " + k + ": mesh sizes outside the limits (or no face)");
  const auto n = static_cast<int>(o.vertices.size());
  for (const auto& t : o.triangles) {
    for (int i : t)
      if (i < 0 || i >= n) finding(kTarget, "obstacle " + k + ": a face index out of range");
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) finding(kTarget, "obstacle " + k + ": a face repeats a corner");
  }
  for (std::size_t f = 0; f < o.frames.size(); ++f) {
    if (o.frames[f].vertices.size() != o.vertices.size()) finding(kTarget, "obstacle " + k + ": a frame of another size");
    if (!std::isfinite(o.frames[f].time) || (f > 0 && !(o.frames[f].time > o.frames[f - 1].time)))
      finding(kTarget, "obstacle " + k + ": frame times not finite and increasing");
  }
}

void check(const std::vector<tecido::Obstacle>& obstacles) {
  if (obstacles.size() > io::kMaxObstacles) finding(kTarget, "accepted more than kMaxObstacles");
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const tecido::Obstacle& o = obstacles[i];
    const std::string k = std::to_string(i);
    if (!within(o.center, io::kMaxCoordinate) || !within(o.velocity, io::kMaxSpeed) ||
        !o.angular_velocity.allFinite())
      finding(kTarget, "obstacle " + k + ": centre, velocity or angular velocity outside the limits");
    if (!(o.friction >= 0.0 && o.friction <= 1.0) || (o.elasticity && !(*o.elasticity >= 0.0 && *o.elasticity <= 1.0)))
      finding(kTarget, "obstacle " + k + ": friction or elasticity outside [0, 1]");
    if (o.kind == tecido::ObstacleKind::Sphere && !(o.radius > 0.0 && std::isfinite(o.radius)))
      finding(kTarget, "obstacle " + k + ": sphere radius " + std::to_string(o.radius));
    if (o.kind == tecido::ObstacleKind::Box) {
      if (!(o.half_extents.minCoeff() > 0.0) || !o.half_extents.allFinite()) finding(kTarget, "obstacle " + k + ": box half extents");
      if (!o.orientation.allFinite() || !(((o.orientation.transpose() * o.orientation) - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= 1e-12))
        finding(kTarget, "obstacle " + k + ": box orientation not orthonormal");
    }
    if (o.kind == tecido::ObstacleKind::Mesh) check_mesh(o, k);
    for (const auto& v : o.vertices)
      if (!within(v, io::kMaxCoordinate)) finding(kTarget, "obstacle " + k + ": a mesh vertex outside |x| <= kMaxCoordinate");
    for (const auto& frame : o.frames)
      for (const auto& v : frame.vertices)
        if (!within(v, io::kMaxCoordinate)) finding(kTarget, "obstacle " + k + ": a keyframe vertex outside |x| <= kMaxCoordinate");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string json = split_and_write(tecido::fuzz::as_text(data, size));
  const std::string scene = folder() + "/scene.json";
  tecido::fuzz::expect_only_input_errors(kTarget, [&] {
    const auto doc = tecido::fuzz::parse_checked(kTarget, json);
    const io::JsonReader r(scene);
    const auto obstacles = io::read_obstacles(r, doc, "/obstacles", scene);
    check(obstacles);
    (void)io::obstacles_use_particle_k(doc);
    const std::vector<tecido::Vec3> x{tecido::Vec3(0, 0, 0), tecido::Vec3(1, 2, 3), tecido::Vec3(-1e12, 0, 1e12)};
    io::check_particles_outside(r, obstacles, "/obstacles", x, {0, 0, 1});
  });
  return 0;
}
