#include "comparisons/suites/forced_contact/scene.h"

#include "comparisons/suites/random.h"
#include "core/scene/cloth_builder.h"

#include <fmt/format.h>

#include <cmath>

namespace tecido::suites::forced_contact {

namespace {

constexpr double kPi = 3.14159265358979323846;

long long steps_of(double seconds, double dt) { return std::llround(seconds / dt); }

/// The point at arc length s from the top of the bar (s < 0: the front layer), the fold being
/// isometric: a half-circle of radius r, then straight down on either side.
Vec3 folded(const ForcedScene& f, double x, double s) {
  const double r = f.bar_radius, quarter = kPi * r / 2;
  if (std::abs(s) <= quarter) return {x, f.bar_height + r * std::cos(s / r), r * std::sin(s / r)};
  return {x, f.bar_height - (std::abs(s) - quarter), s < 0 ? -r : r};
}

ClothGridSpec cloth_spec(const ForcedScene& f) {
  ClothGridSpec c;
  c.rows = f.rows;
  c.cols = f.cols;
  c.spacing = f.spacing;
  c.origin = Vec3::Zero();
  c.axis_u = Vec3::UnitX();
  c.axis_v = Vec3::UnitY();
  c.total_mass = f.total_mass;
  c.stiffness_b = f.stiffness;
  c.stiffness_a = f.stiffness;
  c.damping = 0.0;
  c.elasticity = 0.0;
  for (int r : f.bar_rows)
    for (int col = 0; col < f.cols; ++col) c.pins.push_back({r, col});
  return c;
}

SelfCollisionSettings response_settings(const ForcedScene& f, SelfCollisionResponse response) {
  SelfCollisionSettings s;
  s.response = response;
  s.detection = response == SelfCollisionResponse::Impulse ? SelfCollisionDetection::Continuous : SelfCollisionDetection::Discrete;
  s.strength = f.strength;
  s.every = 1;
  s.impulse_iterations = f.impulse_iterations;
  return s;
}

std::string list(const std::vector<int>& xs) {
  std::string out;
  for (std::size_t k = 0; k < xs.size(); ++k) out += fmt::format("{}{}", k ? ", " : "", xs[k]);
  return out;
}

}  // namespace

Timeline timeline(const ForcedScene& f, double hold, double after_release) {
  Timeline t;
  t.grip = steps_of(f.settle, f.dt);
  t.moved = t.grip + steps_of(f.travel / f.speed, f.dt);
  t.release = t.moved + std::max(1LL, steps_of(hold, f.dt));
  t.end = t.release + steps_of(after_release, f.dt);
  return t;
}

std::vector<Grip> grips(const ForcedScene& f) {
  std::vector<Grip> out(2);
  out[1].direction = -1.0;
  for (int col : f.grip_cols) {
    for (int r : f.front_rows) out[0].particles.push_back(r * f.cols + col);
    for (int r : f.back_rows) out[1].particles.push_back(r * f.cols + col);
  }
  return out;
}

Scene forced_scene(const ForcedScene& f, SelfCollisionResponse response, double hold, double after_release, int s) {
  Scene scene;
  scene.integrator = IntegratorKind::Symplectic;
  scene.dt = f.dt;
  scene.steps = timeline(f, hold, after_release).end;
  scene.seed = substream(f.seed, static_cast<std::uint64_t>(s));
  scene.forces.gravity = Vec3(0.0, -9.81, 0.0);
  scene.forces.air_drag = f.air_drag;
  const ClothGridSpec spec = cloth_spec(f);
  append_cloth(scene, spec);
  Rng rng(scene.seed);
  const double centre = (f.rows - 1) / 2.0, half_width = (f.cols - 1) / 2.0;
  for (int r = 0; r < f.rows; ++r)
    for (int col = 0; col < f.cols; ++col) {
      const int i = cloth_node(spec, scene.cloth_first_particle, r, col);
      Vec3 x = folded(f, (col - half_width) * f.spacing, (r - centre) * f.spacing);
      if (!scene.particles.pinned[i]) x += rng.in_box(-f.offset, f.offset);
      scene.particles.x[i] = x;
    }
  scene.self_collision = response_settings(f, response);
  return scene;
}

io::Json scene_json(const ForcedScene& f) {
  return {{"rows", f.rows},           {"cols", f.cols},
          {"spacing", f.spacing},     {"total_mass", f.total_mass},
          {"stiffness", f.stiffness}, {"air_drag", f.air_drag},
          {"dt", f.dt},               {"bar_height", f.bar_height},
          {"bar_radius", f.bar_radius}, {"bar_rows", f.bar_rows},
          {"front_rows", f.front_rows}, {"back_rows", f.back_rows},
          {"grip_cols", f.grip_cols}, {"settle", f.settle},
          {"travel", f.travel},       {"speed", f.speed},
          {"strength", f.strength},   {"impulse_iterations", f.impulse_iterations},
          {"offset", f.offset},       {"seed", f.seed}};
}

std::string scene_note(const ForcedScene& f) {
  const double quarter = kPi * f.bar_radius / 2;
  return fmt::format(
      "A cloth of {} x {} particles, {} m apart ({} kg: an interior particle carries {:.3g} kg; springs of type A and B at "
      "{} N/m; air drag {} kg/s per particle; symplectic Euler, dt = {} s), folded over a bar: rows {} are fixed on a "
      "half-circle of radius {} m at height {} m along x (arc length {:.3f} m on either side of the top), and the two "
      "halves hang straight down as a front layer (z = -{} m, rows 0 to {}) and a back layer (z = +{} m), a fold that "
      "keeps every distance along the cloth. Every free particle starts offset by a uniform random vector in a cube of "
      "half side {} m (run s: substream({}, s)), the runs' only difference.\n\n"
      "After {} s of settling, a grip takes hold of the front layer's nodes in rows {} and columns {}, another of the "
      "back layer's mirror nodes (rows {}, the same columns): held particles are kinematic (inverse mass 0). The grips "
      "move {} m along z at {} m/s, the front one forward (+z, through the back layer), the back one backward (-z), so "
      "the layers must cross between the bar and the grips. They hold for H, then let go: the particles get their mass "
      "back, at rest, and the cloth is left to itself.\n\n"
      "Responses: GIA and the edge modes detect discretely after every step and push with {} N per particle for one "
      "step (half a particle's weight, the self-contact scene's choice); the impulse response (history-based) detects "
      "continuously, up to {} rounds per step. Why grips: every obstacle of this engine pushes every particle, so a "
      "body pushing one layer pushes the other ahead of it and never forces them through each other; only something "
      "holding each layer (the limbs' grip in the seed's fig. 16) can. Every number here was chosen, and committed "
      "with the claims' rules, before the first run of any response (git history shows the order).\n",
      f.rows, f.cols, f.spacing, f.total_mass, f.total_mass * f.spacing * f.spacing / ((f.rows - 1) * (f.cols - 1) * f.spacing * f.spacing),
      f.stiffness, f.air_drag, f.dt, list(f.bar_rows), f.bar_radius, f.bar_height, quarter, f.bar_radius,
      f.bar_rows.front() - 1, f.bar_radius, f.offset, f.seed, f.settle, list(f.front_rows), list(f.grip_cols),
      list(f.back_rows), f.travel, f.speed, f.strength, f.impulse_iterations);
}

}  // namespace tecido::suites::forced_contact
