#include "comparisons/suites/obstacles/analytic_cases.h"

#include "comparisons/suites/obstacles/box_interior.h"
#include "comparisons/suites/obstacles/theory.h"
#include "comparisons/suites/sweep.h"
#include "core/geometry/obstacle_pose.h"
#include "core/simulation/simulation.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace tecido::suites::obstacles {

namespace {


Obstacle sphere(const Vec3& c, double r) {
  Obstacle o;
  o.kind = ObstacleKind::Sphere;
  o.center = c;
  o.radius = r;
  return o;
}

Obstacle box(const Vec3& c, const Vec3& half, const Eigen::Matrix3d& R = Eigen::Matrix3d::Identity()) {
  Obstacle o;
  o.kind = ObstacleKind::Box;
  o.center = c;
  o.half_extents = half;
  o.orientation = R;
  return o;
}

Scene one_particle(const Vec3& x, const Vec3& v, double k, double h, bool gravity, double g) {
  Scene sc;
  sc.dt = h;
  if (gravity) sc.forces.gravity = Vec3(0, 0, -g);
  sc.particles.add(x, v, 1.0, k, false);
  return sc;
}

io::Json unstable_json(const Simulation& sim) {
  return sim.instability() ? io::Json(sim.instability()->step) : io::Json(nullptr);
}

}  // namespace

double inside_depth(const Obstacle& o, double t, const Vec3& x) {
  if (o.kind == ObstacleKind::Mesh) return 0.0;
  ObstaclePose pose;
  obstacle_pose_at(o, t, pose);
  if (o.kind == ObstacleKind::Sphere) return o.radius - (x - pose.center).norm();
  return point_box_depth(x, OrientedBox{pose.center, pose.rotation, o.half_extents});
}

io::Json sphere_drop_case(const Settings& s) {
  const double top = s.sphere_radius;
  Scene sc = one_particle(Vec3(0, 0, top + s.drop_height), Vec3::Zero(), s.drop_elasticity, s.drop_dt, true, s.g);
  sc.integrator = IntegratorKind::Midpoint;
  sc.obstacles.push_back(sphere(Vec3::Zero(), s.sphere_radius));
  Simulation sim(sc);
  sim.set_log_contacts(true);
  const double t_exact = fall_time(s.drop_height, s.g);
  const double t_end = t_exact * (1.0 + 2.0 * s.drop_elasticity) * 0.98;  // before the second bounce
  double apex_core = kNaN, apex_sampled = -std::numeric_limits<double>::infinity();
  while (sim.time() < t_end && sim.step()) {
    if (sim.contact_log().empty()) continue;
    const Vec3& x = sim.particles().x[0];
    const double vz = sim.particles().v[0].z();
    if (std::isnan(apex_core)) apex_core = x.z() + vz * vz / (2.0 * s.g) - top;
    apex_sampled = std::max(apex_sampled, x.z() - top);
  }
  const double t_core = sim.contact_log().empty() ? kNaN : sim.contact_log().front().time;
  return {{"t_exact", num(t_exact)},
          {"t_core", num(t_core)},
          {"apex_expected", num(rebound_apex(s.drop_height, s.drop_elasticity))},
          {"apex_core", num(apex_core)},
          {"apex_sampled", num(apex_sampled)},
          {"unstable", unstable_json(sim)}};
}

io::Json slide_case(const Settings& s) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(s.slide_angle, Vec3::UnitY()).toRotationMatrix();
  const Vec3 half(5.0, 1.0, 0.5);
  const Vec3 n = R.col(2);
  Scene sc = one_particle(n * (half.z() + s.slide_start_gap), Vec3::Zero(), 0.0, s.slide_dt, true, s.g);
  sc.obstacles.push_back(box(Vec3::Zero(), half, R));
  sc.obstacles.back().friction = s.slide_friction;
  sc.contact.static_threshold = s.slide_static_threshold;
  sc.contact.tangential_threshold = s.slide_tangential_threshold;
  const Vec3 gv(0, 0, -s.g);
  const Vec3 down = (gv - gv.dot(n) * n).normalized();
  const double a = (gv - gv.dot(n) * n).norm();
  Simulation sim(sc);
  const Vec3 x0 = sc.particles.x[0];
  const long long steps = std::llround(s.slide_seconds / s.slide_dt);
  double max_offset = 0.0;
  for (long long k = 0; k < steps && sim.step(); ++k)
    max_offset = std::max(max_offset, std::abs((sim.particles().x[0]).dot(n) - half.z()));
  return {{"expected", num(slide_distance(a, s.slide_friction, s.slide_dt, steps))},
          {"distance", num((sim.particles().x[0] - x0).dot(down))},
          {"max_offset", num(max_offset)},
          {"terminal_speed", num(slide_terminal_speed(a, s.slide_friction, s.slide_dt))},
          {"speed", num(sim.particles().v[0].norm())},
          {"unstable", unstable_json(sim)}};
}

io::Json rest_case(const Settings& s, const std::string& kind) {
  Obstacle o = kind == "sphere" ? sphere(Vec3::Zero(), s.sphere_radius) : box(Vec3::Zero(), Vec3(1.0, 1.0, 0.5));
  if (kind != "sphere" && kind != "box") throw std::invalid_argument("rest_case: unknown obstacle " + kind);
  const double top = kind == "sphere" ? o.radius : o.half_extents.z();
  Scene sc = one_particle(Vec3(0, 0, top), Vec3::Zero(), 0.0, s.rest_dt, true, s.g);
  sc.obstacles.push_back(o);
  Simulation sim(sc);
  double max_offset = 0.0, max_depth = 0.0, max_speed = 0.0;
  for (long long k = 0; k < s.rest_steps && sim.step(); ++k) {
    const Vec3& x = sim.particles().x[0];
    const double d = inside_depth(o, sim.time(), x);
    max_offset = std::max(max_offset, std::abs(d));
    max_depth = std::max(max_depth, d);
    max_speed = std::max(max_speed, sim.particles().v[0].norm());
  }
  return {{"max_offset", num(max_offset)},
          {"max_depth", num(max_depth)},
          {"max_speed", num(max_speed)},
          {"resting", sim.obstacle_contacts().resting().size()},
          {"unstable", unstable_json(sim)}};
}

const std::vector<std::string>& fast_scene_names() {
  static const std::vector<std::string> names = {"thin-box", "moving-sphere", "moving-box", "spinning-box"};
  return names;
}

namespace {

Scene fast_scene(const Settings& s, const std::string& name, double h) {
  if (name == "thin-box") {
    Scene sc = one_particle(Vec3(-1, 0.1, 0.2), Vec3(s.fast_speed, 0, 0), 1.0, h, false, s.g);
    sc.obstacles.push_back(box(Vec3::Zero(), Vec3(s.thin_half_thickness, 1.0, 1.0)));
    return sc;
  }
  Scene sc = one_particle(Vec3(0.5, 0.5, 0.1), Vec3::Zero(), 1.0, h, false, s.g);
  if (name == "moving-sphere") {
    sc.obstacles.push_back(sphere(Vec3(-5, 0.5, 0), 0.5));
    sc.obstacles.back().velocity = Vec3(s.moving_speed, 0, 0);
  } else if (name == "moving-box") {
    sc.obstacles.push_back(box(Vec3(-5, 0.5, 0), Vec3(0.5, 0.5, 0.5)));
    sc.obstacles.back().velocity = Vec3(s.moving_speed, 0, 0);
  } else if (name == "spinning-box") {
    sc.obstacles.push_back(box(Vec3::Zero(), Vec3(1.0, 0.05, 0.5)));
    sc.obstacles.back().angular_velocity = Vec3(0, 0, s.spin_rate);
  } else {
    throw std::invalid_argument("fast_case: unknown scene " + name);
  }
  return sc;
}

}  // namespace

io::Json fast_case(const Settings& s, const std::string& name, double h) {
  const Scene sc = fast_scene(s, name, h);
  Simulation sim(sc);
  long long inside = 0, tunnelled = 0;
  for (long long k = 0; k < s.fast_run_steps && sim.step(); ++k) {
    const Vec3& x = sim.particles().x[0];
    for (const Obstacle& o : sc.obstacles) inside += inside_depth(o, sim.time(), x) > 0.0 ? 1 : 0;
    if (name == "thin-box" && x.x() > s.thin_half_thickness) ++tunnelled;
  }
  const ObstacleCounters& c = sim.obstacle_contacts().counters();
  return {{"steps_inside", inside},
          {"tunnelled", tunnelled},
          {"guard_corrections", c.guard_corrections},
          {"contacts", c.contacts},
          {"unstable", unstable_json(sim)}};
}

}  // namespace tecido::suites::obstacles
