#pragma once
/// tecido's engine as a library (tecido::core, Eigen only): build a scene in code, step it, read
/// its state. The same engine as `tecido run` (docs/design.md sections 2-4): a Simulation of a
/// Scene built here gives, step for step, the same bits as `tecido run` of the scene file that
/// describes the same scene (particles, cloth, springs, planes, obstacles added in the file's
/// order: planes, particles, cloth, springs; tecido::harness::load_scene reads such a file).
///
/// What a scene holds (SI units, double precision):
///  - particles (position, velocity, mass, elasticity k), free or pinned (a pinned particle never
///    moves); springs between two particles (seed eq. 10, with optional damping);
///  - rectangular cloth grids (mass-spring, seed sections 2.1, 3.1.2): particles, springs and a
///    triangle mesh, numbered as ClothGrid says;
///  - gravity and linear air drag;
///  - bounded planes (closed rectangles, two-sided): each step a particle's motion is tested
///    against every plane, the step is bisected to the time of contact and eq. 9's impulse is
///    applied (elastic above a normal speed of 0.01 m/s, static with friction below);
///  - obstacles: spheres and boxes, static or moving at a constant velocity and angular velocity,
///    in the same event loop;
///  - cloth self-collision: detection (discrete or continuous) and one response, as the scene
///    file's "self_collision" key.
/// The integrator (explicit Euler, symplectic Euler, midpoint, RK4) and the step dt are the
/// scene's. Bad arguments throw std::invalid_argument with a one-line message naming the
/// function, the argument and the problem; the scene is left unchanged.
///
/// Thread safety: a Scene or Simulation is used by one thread at a time; different ones may run
/// on different threads. Same scene, same build: the same bits at every thread count.
#include <tecido/geometry.h>

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tecido::core {

namespace detail {
struct SceneData;
struct SimulationData;
struct SceneAccess;
}  // namespace detail

/// The time integrators (seed section 2.2; x' = v, v' = a(t, x, v)):
enum class Integrator {
  Euler,       ///< explicit Euler: x += h v, v += h a                         order 1
  Symplectic,  ///< semi-implicit Euler, the seed's engine: v += h a, x += h v  order 1
  Midpoint,    ///< explicit midpoint                                           order 2
  RK4          ///< classical Runge-Kutta                                       order 4
};

/// A rectangular mass-spring cloth. Node (row r, col c) is particle first + r * cols + c (first:
/// what Scene::add_cloth returns), at origin + c spacing axis_u + r spacing axis_v. Quad (r, c)
/// holds triangles (a, b, d) and (a, d, e) with a = (r, c), b = (r, c+1), d = (r+1, c+1),
/// e = (r+1, c), counter-clockwise about axis_u x axis_v. Springs join nodes one edge apart
/// (horizontal, vertical, both diagonals: `stiffness`) and, when bend_stiffness > 0, two edges
/// apart (`bend_stiffness`); rest length = the initial distance. The total mass is split over
/// the triangles by area and each triangle's share over its corners; pinned nodes have none.
struct ClothGrid {
  int rows = 2;                  ///< nodes along axis_v, >= 2
  int cols = 2;                  ///< nodes along axis_u, >= 2
  double spacing = 0.1;          ///< [m], > 0
  Vec3 origin = Vec3::Zero();    ///< node (0, 0) [m]
  Vec3 axis_u = Vec3::UnitX();   ///< not zero; normalised
  Vec3 axis_v = Vec3::UnitY();   ///< not zero, orthogonal to axis_u; normalised
  double total_mass = 1.0;       ///< [kg], > 0
  double stiffness = 100.0;      ///< springs one edge apart (the seed's type B) [N/m], >= 0
  double bend_stiffness = 0.0;   ///< springs two edges apart (type A) [N/m], >= 0; 0: none
  double damping = 0.0;          ///< every spring's damping [N s/m], >= 0
  double elasticity = 0.5;       ///< restitution k of its nodes' contacts, in [0, 1]
  std::vector<std::array<int, 2>> pins;  ///< (row, col) of the pinned nodes
};

/// A solid sphere obstacle. Kinematic: it pushes particles and is never pushed back.
struct Sphere {
  Vec3 center = Vec3::Zero();  ///< at t = 0 [m]
  double radius = 1.0;         ///< [m], > 0
  Vec3 velocity = Vec3::Zero();          ///< constant translation [m/s]
  Vec3 angular_velocity = Vec3::Zero();  ///< about the centre, world frame [rad/s]
  double friction = 0.0;                 ///< mu of static contacts, in [0, 1]
  std::optional<double> elasticity;      ///< k of its contacts; absent: each particle's own
};

/// A solid box obstacle (kinematic, as Sphere).
struct Box {
  Vec3 center = Vec3::Zero();              ///< at t = 0 [m]
  Vec3 half_extents = Vec3::Ones();        ///< along its local axes [m], each > 0
  Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();  ///< local axes as columns (a rotation)
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();
  double friction = 0.0;
  std::optional<double> elasticity;
};

/// Cloth self-collision in a running simulation (docs/design.md section 5; the scene file's
/// "self_collision" key): after every `every`-th step, detection and one response.
struct SelfCollision {
  enum class Response { None, Gia, Edge1, Edge2, Edge3, GiaEdge3, Impulse };
  Response response = Response::None;  ///< None: detect and count only
  bool continuous = false;  ///< continuous detection (required by Impulse); else discrete
  double strength = 0.0;    ///< [N] per pushed particle (GIA and the edge modes), >= 0
  int every = 1;            ///< >= 1
  int impulse_iterations = 16;  ///< Impulse: rounds of detection per check, >= 1
  int threads = 1;          ///< threads of the detection, >= 1; the result does not depend on it
};

/// A spring of a scene (seed eq. 10): f_i = stiffness (|x_j - x_i| - rest_length) u + damping
/// ((v_j - v_i) . u) u, u the unit vector from i to j, and -f_i on j.
struct SpringInfo {
  int i = 0, j = 0;
  double stiffness = 0.0;    ///< [N/m]
  double rest_length = 0.0;  ///< [m]
  double damping = 0.0;      ///< [N s/m]
};

/// A scene under construction. Copyable; Simulation takes a copy. A moved-from Scene may only be
/// assigned to or destroyed.
class Scene {
 public:
  Scene();
  ~Scene();
  Scene(const Scene& other);
  Scene& operator=(const Scene& other);
  Scene(Scene&& other) noexcept;
  Scene& operator=(Scene&& other) noexcept;

  Scene& set_integrator(Integrator integrator);  ///< default Symplectic
  Scene& set_dt(double dt);                      ///< [s], > 0 (default 0.01)
  Scene& set_gravity(const Vec3& g);             ///< [m/s^2] (default: none)
  Scene& set_air_drag(double c);                 ///< force -c v [kg/s], >= 0 (default: none)
  /// The steps a whole run takes (the scene file's "steps"; default 0): what sim.run(steps())
  /// runs. >= 0.
  Scene& set_steps(long long steps);
  Integrator integrator() const;
  double dt() const;
  long long steps() const;

  /// A free particle; returns its index. mass > 0, elasticity in [0, 1].
  int add_particle(const Vec3& position, const Vec3& velocity, double mass, double elasticity = 0.5);
  /// A pinned particle (never moves); returns its index.
  int add_pinned_particle(const Vec3& position);
  /// A spring between particles i != j; rest_length < 0 means their current distance. Returns
  /// its index among the scene's springs.
  int add_spring(int i, int j, double stiffness, double rest_length = -1.0, double damping = 0.0);
  /// A cloth grid: returns the index of its node (0, 0). One cloth per scene.
  int add_cloth(const ClothGrid& cloth);
  /// A bounded plane (normal and forward need not be unit; forward is made orthogonal to the
  /// normal); friction in [0, 1]. Returns its index.
  int add_plane(const Rectangle& rectangle, double friction = 0.0);
  /// Obstacles; each returns its index among the obstacles. A free particle must not start
  /// inside one (checked by Simulation).
  int add_sphere(const Sphere& sphere);
  int add_box(const Box& box);
  /// Self-collision of the cloth (add the cloth first).
  Scene& set_self_collision(const SelfCollision& settings);

  std::size_t particle_count() const;
  std::size_t spring_count() const;
  /// Initial positions and velocities, inverse masses (0 for a pinned particle) and the springs
  /// in force order (a cloth's as ClothGrid lists them): what a user's engine needs to run the
  /// same scene (e.g. as a tecido_scene of tecido/plugin.h).
  const std::vector<Vec3>& positions() const;
  const std::vector<Vec3>& velocities() const;
  const std::vector<double>& inverse_masses() const;
  std::vector<SpringInfo> springs() const;
  /// The gravity (zero when none) and the linear drag (0 when none).
  Vec3 gravity() const;
  double air_drag() const;
  /// The cloth's triangle mesh over particle indices (empty without a cloth).
  const Faces& triangles() const;

 private:
  friend struct detail::SceneAccess;
  std::unique_ptr<detail::SceneData> d_;
};

/// Why a run stopped: the first step that made a position or a velocity NaN or infinite.
struct Divergence {
  long long step = 0;    ///< 1-based
  int particle = -1;
  std::string quantity;  ///< "position" or "velocity"
};

/// Contact counters of a run (the "contacts" of `tecido run --json`).
struct ContactCounts {
  long long events = 0;        ///< bisected contact events
  long long elastic = 0;       ///< contacts answered by the elastic branch of eq. 9
  long long static_contacts = 0;  ///< ... by the static branch
  long long bisections = 0;    ///< integrator calls spent bisecting
  long long event_cap_hits = 0;  ///< steps whose event cap was reached
  std::size_t resting_now = 0;   ///< particle-plane pairs in resting contact now
  long long obstacle_contacts = 0;  ///< particle-obstacle contacts resolved
};

/// Self-collision counters of a run (the "self_collision" of `tecido run --json`).
struct SelfCollisionCounts {
  long long checks = 0;          ///< steps after which detection ran
  long long contact_checks = 0;  ///< ... and found a contact
  long long pairs = 0;           ///< pairs (or contacts, continuous) found, summed
  std::size_t pairs_now = 0;     ///< found by the latest check
};

/// One run of a scene. Move-only; a moved-from Simulation may only be assigned to or destroyed.
class Simulation {
 public:
  /// Takes a copy of the scene. Throws std::invalid_argument when it has no particle, or a free
  /// particle starts inside a sphere or a box.
  explicit Simulation(const Scene& scene);
  ~Simulation();
  Simulation(Simulation&& other) noexcept;
  Simulation& operator=(Simulation&& other) noexcept;

  /// One step of dt. False once the run has diverged (later calls do nothing).
  bool step();
  /// Up to `steps` steps (>= 0), stopping at divergence; false when diverged.
  bool run(long long steps);

  const std::vector<Vec3>& positions() const;   ///< [m], by particle index
  const std::vector<Vec3>& velocities() const;  ///< [m/s]
  double time() const;                          ///< steps_done() * dt [s]
  long long steps_done() const;
  /// The divergence, once the run has diverged ("status unstable" in `tecido run`).
  const std::optional<Divergence>& divergence() const;
  bool diverged() const { return divergence().has_value(); }
  ContactCounts contacts() const;
  /// Zero without self-collision.
  SelfCollisionCounts self_collision() const;

 private:
  std::unique_ptr<detail::SimulationData> d_;
};

}  // namespace tecido::core
