#include "comparisons/suites/obstacles/block_scene.h"

#include "comparisons/io/scene_json.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace tecido::suites::obstacles {

namespace {

/// The box axis (0, 1, 2) nearest `up` in direction.
int top_axis(const OrientedBox& box, const Vec3& up) {
  const Vec3 u = box.rotation.transpose() * up;
  int a = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(u[k]) > std::abs(u[a])) a = k;
  return a;
}

/// The grid axis (axis_u or axis_v) parallel to w, oriented along w; throws when neither is.
Vec3 grid_axis_along(const ClothGridSpec& c, const Vec3& w) {
  for (const Vec3& g : {c.axis_u, c.axis_v}) {
    const double d = g.normalized().dot(w);
    if (std::abs(d) >= 1.0 - 1e-12) return d > 0.0 ? Vec3(g.normalized()) : Vec3(-g.normalized());
  }
  throw std::invalid_argument("edge_insets: the block's horizontal axes are not parallel to the cloth grid's axes");
}

/// Distance in spacings from coordinate e (in spacings along an axis) down to the nearest integer
/// at or below it; a value within 1e-9 of an integer counts as that integer.
double inset_below(double e) {
  const double r = std::round(e);
  if (std::abs(e - r) < 1e-9) return 0.0;
  return e - std::floor(e);
}

}  // namespace

Scene block_scene(const Settings& s, const std::string& data_dir, int n, bool edge_contacts) {
  for (std::size_t k = 0; k < s.block_sides.size(); ++k)
    if (s.block_sides[k] == n) {
      Scene sc = io::load_scene(data_dir + "/scenes/" + s.block_files[k]);
      if (sc.obstacles.empty() || sc.obstacles.front().kind != ObstacleKind::Box || !sc.cloth || sc.cloth->rows != n)
        throw std::invalid_argument(std::string(s.block_files[k]) + ": expected an n x n cloth over a box");
      sc.edge_contacts = edge_contacts;
      return sc;
    }
  throw std::invalid_argument("block_scene: no block scene with " + std::to_string(n) + " x " + std::to_string(n));
}

Scene sphere_scene(const Settings& s, const std::string& data_dir) {
  Scene sc = io::load_scene(data_dir + "/scenes/" + s.sphere_file);
  if (sc.obstacles.empty() || sc.obstacles.front().kind != ObstacleKind::Sphere || !sc.cloth)
    throw std::invalid_argument(std::string(s.sphere_file) + ": expected a cloth over a sphere");
  return sc;
}

long long run_steps(const Settings& s, const Scene& scene) {
  return s.block_seconds > 0.0 ? std::llround(s.block_seconds / scene.dt) : scene.steps;
}

OrientedBox block_of(const Scene& scene) {
  const Obstacle& o = scene.obstacles.front();
  return OrientedBox{o.center, o.orientation, o.half_extents};
}

std::vector<std::array<int, 2>> stiff_springs(const Scene& scene) {
  std::vector<std::array<int, 2>> out;
  for (const Spring& sp : scene.forces.springs)
    if (sp.stiffness > 0.0) out.push_back({sp.i, sp.j});
  return out;
}

Vec3 up_of(const Scene& scene) {
  const Vec3 g = scene.forces.gravity.value_or(Vec3::Zero());
  return g.norm() > 0.0 ? Vec3(-g.normalized()) : Vec3::UnitZ();
}

double height_above_top(const OrientedBox& box, const Vec3& up, const Vec3& x, bool* over) {
  const Vec3 u = box.rotation.transpose() * up;
  const int a = top_axis(box, up);
  const Vec3 q = box.rotation.transpose() * (x - box.center);
  const double sign = u[a] > 0.0 ? 1.0 : -1.0;
  bool inside_outline = true;
  for (int k = 0; k < 3; ++k)
    if (k != a) inside_outline = inside_outline && std::abs(q[k]) < box.half[k];
  if (over) *over = inside_outline;
  return sign * q[a] - box.half[a];
}

std::array<double, 4> edge_insets(const Scene& scene) {
  if (!scene.cloth || !(scene.cloth->spacing > 0.0)) throw std::invalid_argument("edge_insets: the scene has no cloth grid");
  const ClothGridSpec& c = *scene.cloth;
  const OrientedBox box = block_of(scene);
  const int a = top_axis(box, up_of(scene));
  std::array<double, 4> out{};
  int slot = 0;
  for (int k = 0; k < 3; ++k) {
    if (k == a) continue;
    const Vec3 w = box.rotation.col(k);
    const Vec3 g = grid_axis_along(c, w);  // the grid's direction along +w
    for (double sign : {1.0, -1.0}) {
      // The edge's coordinate along +w in spacings from the grid's origin; the top face lies on
      // the -sign side of it, so the nearest column on that side is below (+ edge) or above.
      const double e = (box.center + sign * box.half[k] * w - c.origin).dot(g) / c.spacing;
      out[slot++] = inset_below(sign * e);
    }
  }
  return out;
}

int springs_across_outline(const Scene& scene) {
  const OrientedBox box = block_of(scene);
  const Vec3 up = up_of(scene);
  const auto& x = scene.particles.x;
  int count = 0;
  for (const auto& sp : stiff_springs(scene)) {
    bool over_i = false, over_j = false;
    height_above_top(box, up, x[sp[0]], &over_i);
    height_above_top(box, up, x[sp[1]], &over_j);
    count += over_i != over_j ? 1 : 0;
  }
  return count;
}

double initial_gap(const Scene& scene) {
  const Obstacle& o = scene.obstacles.front();
  const Vec3 up = up_of(scene);
  double gap = std::numeric_limits<double>::infinity();
  for (const Vec3& x : scene.particles.x) {
    const double h = o.kind == ObstacleKind::Box ? height_above_top(block_of(scene), up, x, nullptr)
                                                 : (x - o.center).dot(up) - o.radius;
    gap = std::min(gap, h);
  }
  return gap;
}

}  // namespace tecido::suites::obstacles
