#include "comparisons/suites/obstacles/bullet_cases.h"

#include "comparisons/suites/obstacles/analytic_cases.h"
#include "comparisons/suites/obstacles/block_scene.h"
#include "comparisons/suites/obstacles/box_interior.h"
#include "comparisons/suites/obstacles/theory.h"
#include "comparisons/suites/sweep.h"
#include "core/simulation/simulation.h"
#include "reference/bullet_obstacle_world.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tecido::suites::obstacles {

namespace {


/// What the suite measures of one engine's run, step end by step end.
struct Track {
  double t_onset = kNaN;
  double max_penetration = 0.0;
  int max_through = 0;
  io::Json frames = io::Json::array();
  io::Json unstable = nullptr;
  double rest_height = kNaN;

  io::Json json() const {
    return {{"t_onset", num(t_onset)},   {"max_penetration", num(max_penetration)}, {"max_through", max_through},
            {"frames", frames},         {"rest_height", num(rest_height)},         {"unstable", unstable}};
  }
};

/// What observe() needs besides the state: the scene, its stiff springs when the obstacle is the
/// block (else empty), the depth that counts as through, the frame interval.
struct Watch {
  const Scene* scene;
  std::vector<std::array<int, 2>> springs;
  double through_depth;
  long long every;
};

/// One step end: penetration of every node into the obstacle, onset (the first step end at which
/// some node's velocity departs from the free fall `v_free` by more than kDeparture: the cloth
/// falls flat and unstretched until something touches) and, for the block, the springs through
/// it; a frame every `every` steps.
void observe(Track& tr, const Watch& w, const std::vector<Vec3>& x, const std::vector<Vec3>& v, const Vec3& v_free,
             double t, long long k) {
  constexpr double kDeparture = 1e-6;  // [m/s]
  const Scene& sc = *w.scene;
  const Obstacle& o = sc.obstacles.front();
  double deepest_node = 0.0, departure = 0.0;
  for (const Vec3& p : x) deepest_node = std::max(deepest_node, inside_depth(o, t, p));
  for (const Vec3& u : v) departure = std::max(departure, (u - v_free).norm());
  tr.max_penetration = std::max(tr.max_penetration, deepest_node);
  if (std::isnan(tr.t_onset) && departure > kDeparture) tr.t_onset = t;
  if (w.springs.empty()) return;
  double deepest = 0.0;
  const int through = springs_through_box(x, w.springs, block_of(sc), w.through_depth, &deepest);
  tr.max_through = std::max(tr.max_through, through);
  if (k % w.every == 0) tr.frames.push_back({num(t), through, num(deepest)});
}

/// Sphere: the cloth's centre node's height above the surface. Block: the mean height above the
/// top face of the nodes over it (inside the block too: Bullet's may sink).
double top_rest_height(const Scene& sc, const std::vector<Vec3>& x, bool block) {
  const Obstacle& o = sc.obstacles.front();
  if (!block) {
    const int n = sc.cloth->rows, m = sc.cloth->cols;
    return -inside_depth(o, 0.0, x[sc.cloth_first_particle + (n / 2) * m + m / 2]);
  }
  const OrientedBox b = block_of(sc);
  const Vec3 up = up_of(sc);
  double sum = 0.0;
  int count = 0;
  for (const Vec3& p : x) {
    bool over = false;
    const double h = height_above_top(b, up, p, &over);
    if (over && h > -2.0 * b.half.maxCoeff()) sum += h, ++count;
  }
  return count ? sum / count : kNaN;
}

io::Json run_both(const Settings& s, const Scene& sc, bool block) {
  const long long steps = run_steps(s, sc);
  const Watch w{&sc, block ? stiff_springs(sc) : std::vector<std::array<int, 2>>{}, s.through_depth,
                std::max(1LL, steps / s.block_frames)};
  Track core, bt;
  Simulation sim(sc);
  sim.set_log_contacts(true);
  reference::ObstacleWorldOptions opt;
  opt.voxel_size = s.bullet_voxel;
  opt.collision_margin = s.bullet_margin;
  reference::BulletObstacleWorld bullet(sc, opt);
  const Vec3 g = sc.forces.gravity.value_or(Vec3::Zero());
  for (long long k = 1; k <= steps; ++k) {
    // Free fall after k steps of semi-implicit Euler from rest (both engines): v = g k h.
    const Vec3 v_free = g * (static_cast<double>(k) * sc.dt);
    if (core.unstable.is_null() && sim.step()) {
      observe(core, w, sim.particles().x, sim.particles().v, v_free, sim.time(), k);
    } else if (core.unstable.is_null()) {
      core.unstable = k;
    }
    if (bt.unstable.is_null() && bullet.step()) {
      observe(bt, w, bullet.positions(), bullet.velocities(), v_free, bullet.time(), k);
    } else if (bt.unstable.is_null()) {
      bt.unstable = k;
    }
  }
  const double t_contact_core = sim.contact_log().empty() ? kNaN : sim.contact_log().front().time;
  core.t_onset = t_contact_core;  // core's own first contact (its cloth leaves free fall at once under air drag)
  core.rest_height = top_rest_height(sc, sim.particles().x, block);
  bt.rest_height = top_rest_height(sc, bullet.positions(), block);
  const double g_norm = sc.forces.gravity.value_or(Vec3::Zero()).norm();
  return {{"t_onset_expected", num(fall_time(initial_gap(sc), g_norm))},
          {"dt", num(sc.dt)},
          {"t_contact_core", num(t_contact_core)},
          {"contact_distance", num(opt.collision_margin)},
          {"core", core.json()},
          {"bullet", bt.json()},
          {"not_modelled", bullet.not_modelled()}};
}

}  // namespace

io::Json bullet_sphere_case(const Settings& s, const std::string& data_dir) {
  return run_both(s, sphere_scene(s, data_dir), false);
}

io::Json bullet_block_case(const Settings& s, const std::string& data_dir, int n) {
  return run_both(s, block_scene(s, data_dir, n, false), true);
}

}  // namespace tecido::suites::obstacles
