#include "comparisons/suites/self_contact/scene_applier.h"

#include "comparisons/io/input_error.h"
#include "core/scene/cloth_builder.h"

#include <cmath>
#include <memory>

namespace tecido::suites::self_contact {

void check_base_scene(const Scene& base, const std::string& file) {
  if (!base.cloth) throw io::InputError(file, "/cloth", "the experiment needs a cloth");
  Scene cloth_only;
  append_cloth(cloth_only, *base.cloth);
  if (base.particles.size() != cloth_only.particles.size())
    throw io::InputError(file, "/particles", "the experiment's scene must hold the cloth's particles only");
  if (base.forces.springs.size() != cloth_only.forces.springs.size())
    throw io::InputError(file, "/springs", "the experiment's scene must hold the cloth's springs only");
  const auto& w = base.forces.wind;
  if (!w || !w->swirl || !w->random)
    throw io::InputError(file, "/wind", "the experiment needs a swirling random wind ({\"force\",\"swirl\",\"random\"})");
  if (!(w->force.norm() > 0.0)) throw io::InputError(file, "/wind/force", "must not be zero (its direction is kept)");
  if (!base.self_collision) throw io::InputError(file, "/self_collision", "the experiment needs self_collision");
}

Interpretation scene_interpretation(const Scene& base) {
  Interpretation in;
  in.strength = base.self_collision->strength;
  in.air_drag = base.forces.air_drag.value_or(0.0);
  in.swirl_rate = base.forces.wind->rate;
  in.heading_diffusion = base.forces.wind->random->diffusion;
  in.pins = base.cloth->pins;
  return in;
}

namespace {

ClothGridSpec cell_cloth(const ClothGridSpec& base, const Cell& cell, const Interpretation& in) {
  ClothGridSpec spec = base;
  spec.pins = in.pins;
  if (in.elasticity_as == "stiffness") {
    spec.stiffness_b *= cell.elasticity;
    spec.stiffness_a *= cell.elasticity;
  } else if (in.elasticity_as == "restitution") {
    spec.elasticity = cell.elasticity;
  } else {
    throw io::UsageError("elasticity must be read as stiffness or restitution, not \"" + in.elasticity_as + "\"");
  }
  return spec;
}

Wind cell_wind(const Wind& base, const Cell& cell, const Interpretation& in, std::uint64_t wind_seed, double T,
               int free_particles) {
  Wind w = base;
  double magnitude = cell.wind;
  if (in.wind_per == "total") {
    magnitude /= free_particles > 0 ? free_particles : 1;
  } else if (in.wind_per != "particle") {
    throw io::UsageError("the wind must act per particle or in total, not \"" + in.wind_per + "\"");
  }
  w.force = base.force.normalized() * magnitude;
  w.rate = in.swirl_rate;
  auto h = std::make_shared<RandomHeading>(*base.random);
  h->seed = wind_seed;
  h->diffusion = in.heading_diffusion;
  h->prepare(T);
  w.random = std::move(h);
  return w;
}

}  // namespace

Scene apply_cell(const Scene& base, const Cell& cell, const Interpretation& in, std::uint64_t wind_seed,
                 double simulated_time) {
  Scene s;
  s.integrator = base.integrator;
  s.seed = base.seed;
  s.dt = cell.dt;
  s.steps = std::llround(simulated_time / cell.dt);
  s.planes = base.planes;
  s.contact = base.contact;
  s.forces.gravity = base.forces.gravity;
  s.forces.air_drag = in.air_drag;
  append_cloth(s, cell_cloth(*base.cloth, cell, in));
  int free_particles = 0;
  for (double w : s.particles.inv_mass) free_particles += w != 0.0;
  s.forces.wind = cell_wind(*base.forces.wind, cell, in, wind_seed, simulated_time, free_particles);
  SelfCollisionSettings sc = *base.self_collision;
  sc.response = *parse_self_collision_response(mode_response_name(cell.mode));
  sc.strength = in.strength;
  sc.every = 1;
  s.self_collision = sc;
  return s;
}

}  // namespace tecido::suites::self_contact
