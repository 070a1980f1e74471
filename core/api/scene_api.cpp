// The public Scene of include/tecido/simulation.h: each call checks its arguments (a one-line
// std::invalid_argument naming the function and the argument) and then builds core's Scene with
// the code the scene file's reader uses (append_cloth, make_bounded_plane, Particles::add).
#include "core/api/scene_access.h"
#include "core/geometry/bounded_plane.h"
#include "core/scene/cloth_builder.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace tecido::core {

namespace {

[[noreturn]] void refuse(const char* function, const std::string& problem) {
  throw std::invalid_argument(std::string("tecido::core::Scene::") + function + ": " + problem);
}

std::string number_text(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

void require_finite(const char* function, const char* name, const Vec3& v) {
  if (!v.allFinite()) refuse(function, std::string(name) + " must be finite");
}

/// x in [lo, hi] (NaN refused).
void require_in(const char* function, const char* name, double x, double lo, double hi) {
  if (!(x >= lo && x <= hi))
    refuse(function, std::string(name) + " must be in [" + number_text(lo) + ", " + number_text(hi) + "], got " +
                         number_text(x));
}

void require_positive(const char* function, const char* name, double x) {
  if (!(x > 0.0 && std::isfinite(x))) refuse(function, std::string(name) + " must be > 0 and finite, got " + number_text(x));
}

constexpr double kHuge = 1e300;

/// The motion and contact keys an obstacle shares, checked.
/// An obstacle of `kind` at the shape's centre with its motion and contact fields (Sphere and Box
/// share them), after checking those fields; the caller fills the shape's own.
template <class Shape>
Obstacle moving_obstacle(const char* function, ObstacleKind kind, const Shape& s) {
  require_finite(function, "center", s.center);
  require_finite(function, "velocity", s.velocity);
  require_finite(function, "angular_velocity", s.angular_velocity);
  require_in(function, "friction", s.friction, 0.0, 1.0);
  if (s.elasticity) require_in(function, "elasticity", *s.elasticity, 0.0, 1.0);
  Obstacle o;
  o.kind = kind;
  o.center = s.center;
  o.velocity = s.velocity;
  o.angular_velocity = s.angular_velocity;
  o.friction = s.friction;
  o.elasticity = s.elasticity;
  return o;
}

::tecido::IntegratorKind internal(Integrator k) {
  switch (k) {
    case Integrator::Euler: return IntegratorKind::Euler;
    case Integrator::Symplectic: return IntegratorKind::Symplectic;
    case Integrator::Midpoint: return IntegratorKind::Midpoint;
    case Integrator::RK4: return IntegratorKind::RK4;
  }
  refuse("set_integrator", "unknown integrator");
}

SelfCollisionResponse internal(SelfCollision::Response r) {
  switch (r) {
    case SelfCollision::Response::None: return SelfCollisionResponse::None;
    case SelfCollision::Response::Gia: return SelfCollisionResponse::Gia;
    case SelfCollision::Response::Edge1: return SelfCollisionResponse::Edge1;
    case SelfCollision::Response::Edge2: return SelfCollisionResponse::Edge2;
    case SelfCollision::Response::Edge3: return SelfCollisionResponse::Edge3;
    case SelfCollision::Response::GiaEdge3: return SelfCollisionResponse::GiaEdge3;
    case SelfCollision::Response::Impulse: return SelfCollisionResponse::Impulse;
  }
  refuse("set_self_collision", "unknown response");
}

}  // namespace

Scene::Scene() : d_(std::make_unique<detail::SceneData>()) {}
Scene::~Scene() = default;
Scene::Scene(const Scene& other) : d_(std::make_unique<detail::SceneData>(*other.d_)) {}
Scene& Scene::operator=(const Scene& other) {
  if (this != &other) d_ = std::make_unique<detail::SceneData>(*other.d_);
  return *this;
}
Scene::Scene(Scene&& other) noexcept = default;
Scene& Scene::operator=(Scene&& other) noexcept = default;

Scene& Scene::set_integrator(Integrator integrator) {
  d_->scene.integrator = internal(integrator);
  return *this;
}

Scene& Scene::set_dt(double dt) {
  require_positive("set_dt", "dt", dt);
  d_->scene.dt = dt;
  return *this;
}

Scene& Scene::set_gravity(const Vec3& g) {
  require_finite("set_gravity", "g", g);
  d_->scene.forces.gravity = g;
  return *this;
}

Scene& Scene::set_air_drag(double c) {
  require_in("set_air_drag", "c", c, 0.0, kHuge);
  d_->scene.forces.air_drag = c;
  return *this;
}

Scene& Scene::set_steps(long long steps) {
  if (steps < 0) refuse("set_steps", "steps must be >= 0, got " + std::to_string(steps));
  d_->scene.steps = steps;
  return *this;
}

long long Scene::steps() const { return d_->scene.steps; }

Integrator Scene::integrator() const {
  switch (d_->scene.integrator) {
    case IntegratorKind::Euler: return Integrator::Euler;
    case IntegratorKind::Midpoint: return Integrator::Midpoint;
    case IntegratorKind::RK4: return Integrator::RK4;
    case IntegratorKind::Symplectic: break;
  }
  return Integrator::Symplectic;
}

double Scene::dt() const { return d_->scene.dt; }

int Scene::add_particle(const Vec3& position, const Vec3& velocity, double mass, double elasticity) {
  require_finite("add_particle", "position", position);
  require_finite("add_particle", "velocity", velocity);
  require_positive("add_particle", "mass", mass);
  if (!std::isfinite(1.0 / mass)) refuse("add_particle", "mass too small: its inverse must be finite");
  require_in("add_particle", "elasticity", elasticity, 0.0, 1.0);
  d_->scene.particles.add(position, velocity, mass, elasticity, false);
  return static_cast<int>(d_->scene.particles.size() - 1);
}

int Scene::add_pinned_particle(const Vec3& position) {
  require_finite("add_pinned_particle", "position", position);
  d_->scene.particles.add(position, Vec3::Zero(), 0.0, 1.0, true);  // k 1.0: the scene file's default
  return static_cast<int>(d_->scene.particles.size() - 1);
}

int Scene::add_spring(int i, int j, double stiffness, double rest_length, double damping) {
  const int n = static_cast<int>(d_->scene.particles.size());
  if (i < 0 || i >= n || j < 0 || j >= n)
    refuse("add_spring", "particle index out of range [0, " + std::to_string(n) + "): " + std::to_string(i) + ", " +
                             std::to_string(j));
  if (i == j) refuse("add_spring", "a spring needs two different particles, got " + std::to_string(i) + " twice");
  require_in("add_spring", "stiffness", stiffness, 0.0, kHuge);
  require_in("add_spring", "damping", damping, 0.0, kHuge);
  if (std::isnan(rest_length) || rest_length > kHuge) refuse("add_spring", "rest_length must be finite");
  const auto& x = d_->scene.particles.x;
  const double rest = rest_length < 0.0 ? (x[j] - x[i]).norm() : rest_length;
  d_->scene.forces.springs.push_back(Spring{i, j, stiffness, rest, damping});
  return static_cast<int>(d_->scene.forces.springs.size() - 1);
}

int Scene::add_cloth(const ClothGrid& c) {
  const char* f = "add_cloth";
  if (d_->scene.cloth) refuse(f, "the scene has a cloth already (one cloth per scene)");
  if (c.rows < 2 || c.cols < 2)
    refuse(f, "rows and cols must be >= 2, got " + std::to_string(c.rows) + " x " + std::to_string(c.cols));
  require_positive(f, "spacing", c.spacing);
  require_finite(f, "origin", c.origin);
  require_finite(f, "axis_u", c.axis_u);
  require_finite(f, "axis_v", c.axis_v);
  if (!(c.axis_u.norm() > 1e-12)) refuse(f, "axis_u must not be zero");
  if (!(c.axis_v.norm() > 1e-12)) refuse(f, "axis_v must not be zero");
  ClothGridSpec spec;
  spec.rows = c.rows;
  spec.cols = c.cols;
  spec.spacing = c.spacing;
  spec.origin = c.origin;
  spec.axis_u = c.axis_u.normalized();
  spec.axis_v = c.axis_v.normalized();
  if (std::abs(spec.axis_u.dot(spec.axis_v)) > 1e-9) refuse(f, "axis_v must be orthogonal to axis_u");
  require_positive(f, "total_mass", c.total_mass);
  if (!std::isfinite(static_cast<double>(c.rows) * c.cols / c.total_mass))
    refuse(f, "total_mass too small: each node's inverse mass must be finite");
  require_in(f, "stiffness", c.stiffness, 0.0, kHuge);
  require_in(f, "bend_stiffness", c.bend_stiffness, 0.0, kHuge);
  require_in(f, "damping", c.damping, 0.0, kHuge);
  require_in(f, "elasticity", c.elasticity, 0.0, 1.0);
  for (const auto& p : c.pins)
    if (p[0] < 0 || p[0] >= c.rows || p[1] < 0 || p[1] >= c.cols)
      refuse(f, "pin (" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + ") is outside the " +
                    std::to_string(c.rows) + " x " + std::to_string(c.cols) + " grid");
  spec.total_mass = c.total_mass;
  spec.stiffness_b = c.stiffness;
  spec.stiffness_a = c.bend_stiffness;
  spec.damping = c.damping;
  spec.elasticity = c.elasticity;
  spec.pins = c.pins;
  append_cloth(d_->scene, spec);
  return d_->scene.cloth_first_particle;
}

int Scene::add_plane(const Rectangle& r, double friction) {
  const char* f = "add_plane";
  require_finite(f, "position", r.position);
  require_finite(f, "normal", r.normal);
  require_finite(f, "forward", r.forward);
  if (!(r.normal.norm() > 1e-12)) refuse(f, "normal must not be zero");
  if (!(r.forward.norm() > 1e-12)) refuse(f, "forward must not be zero");
  if (r.normal.normalized().cross(r.forward.normalized()).norm() < 1e-9) refuse(f, "forward is parallel to the normal");
  require_in(f, "half_forward", r.half_forward, 0.0, kHuge);
  require_in(f, "half_right", r.half_right, 0.0, kHuge);
  require_in(f, "friction", friction, 0.0, 1.0);
  d_->scene.planes.push_back(
      make_bounded_plane(r.position, r.normal, r.forward, Vec2(r.half_forward, r.half_right), friction));
  return static_cast<int>(d_->scene.planes.size() - 1);
}

int Scene::add_sphere(const Sphere& s) {
  Obstacle o = moving_obstacle("add_sphere", ObstacleKind::Sphere, s);
  require_positive("add_sphere", "radius", s.radius);
  o.radius = s.radius;
  d_->scene.obstacles.push_back(std::move(o));
  return static_cast<int>(d_->scene.obstacles.size() - 1);
}

int Scene::add_box(const Box& b) {
  const char* f = "add_box";
  Obstacle o = moving_obstacle(f, ObstacleKind::Box, b);
  for (int k = 0; k < 3; ++k) require_positive(f, "half_extents", b.half_extents[k]);
  if (!b.orientation.allFinite() || !(b.orientation.transpose() * b.orientation).isIdentity(1e-9) ||
      !(b.orientation.determinant() > 0.0))
    refuse(f, "orientation must be a rotation (orthonormal columns, determinant 1)");
  o.half_extents = b.half_extents;
  o.orientation = b.orientation;
  d_->scene.obstacles.push_back(std::move(o));
  return static_cast<int>(d_->scene.obstacles.size() - 1);
}

Scene& Scene::set_self_collision(const SelfCollision& s) {
  const char* f = "set_self_collision";
  if (d_->scene.triangles.empty()) refuse(f, "self-collision needs a cloth (add it first)");
  if (s.response == SelfCollision::Response::Impulse && !s.continuous)
    refuse(f, "the impulse response needs continuous detection");
  require_in(f, "strength", s.strength, 0.0, kHuge);
  if (s.every < 1) refuse(f, "every must be >= 1, got " + std::to_string(s.every));
  if (s.impulse_iterations < 1) refuse(f, "impulse_iterations must be >= 1, got " + std::to_string(s.impulse_iterations));
  if (s.threads < 1) refuse(f, "threads must be >= 1, got " + std::to_string(s.threads));
  SelfCollisionSettings settings;
  settings.response = internal(s.response);
  settings.detection = s.continuous ? SelfCollisionDetection::Continuous : SelfCollisionDetection::Discrete;
  settings.strength = s.strength;
  settings.every = s.every;
  settings.impulse_iterations = s.impulse_iterations;
  settings.threads = s.threads;
  d_->scene.self_collision = settings;
  return *this;
}

std::size_t Scene::particle_count() const { return d_->scene.particles.size(); }
std::size_t Scene::spring_count() const { return d_->scene.forces.springs.size(); }
const std::vector<Vec3>& Scene::positions() const { return d_->scene.particles.x; }
const std::vector<Vec3>& Scene::velocities() const { return d_->scene.particles.v; }
const std::vector<double>& Scene::inverse_masses() const { return d_->scene.particles.inv_mass; }
Vec3 Scene::gravity() const { return d_->scene.forces.gravity.value_or(Vec3::Zero()); }
double Scene::air_drag() const { return d_->scene.forces.air_drag.value_or(0.0); }

std::vector<SpringInfo> Scene::springs() const {
  std::vector<SpringInfo> out;
  out.reserve(d_->scene.forces.springs.size());
  for (const Spring& s : d_->scene.forces.springs) out.push_back({s.i, s.j, s.stiffness, s.rest_length, s.damping});
  return out;
}

const Faces& Scene::triangles() const { return d_->scene.triangles; }

}  // namespace tecido::core
