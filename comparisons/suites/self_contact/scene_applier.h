#pragma once
/// One run's Scene: the experiment's base scene (data/scenes/seed_fig21_self_contact.json, read
/// and validated once) with a cell, a reading of the seed and a wind seed applied. The base
/// scene must hold exactly one cloth (no other particles or springs), a swirling random wind and
/// self_collision. The run's scene copies the base's integrator, gravity, planes and contact
/// settings and sets:
///  - dt = the cell's step, steps = round(T / dt);
///  - air drag and the swirl's rate from the reading; the wind's magnitude to the cell's wind
///    (per free particle, or that total split over them), its direction, axis and phase as in the
///    base; its random heading (core/dynamics/random_wind.h) with `wind_seed`, the reading's
///    heading diffusion, the base's knot interval, knots prepared for T;
///  - the cloth rebuilt from the base's grid with the reading's pins and the cell's elasticity
///    (scaling stiffness_b and stiffness_a, or as the restitution quotient);
///  - self_collision: the cell's response (none, edge1..3), the reading's strength, every step.
#include "comparisons/suites/self_contact/grid.h"
#include "comparisons/suites/self_contact/interpretation.h"
#include "core/scene/scene.h"

#include <cstdint>
#include <string>

namespace tecido::suites::self_contact {

/// Throws io::InputError (naming `file` and the JSON pointer) when `base` is not a scene the
/// experiment can vary (see the file comment).
void check_base_scene(const Scene& base, const std::string& file);

/// The reading the base scene itself gives: elasticity as stiffness, wind per particle, and the
/// file's strength, drag, swirl rate, heading diffusion and pins.
Interpretation scene_interpretation(const Scene& base);

/// The scene of one run (base checked by check_base_scene).
Scene apply_cell(const Scene& base, const Cell& cell, const Interpretation& in, std::uint64_t wind_seed,
                 double simulated_time);

}  // namespace tecido::suites::self_contact
