#pragma once
/// The forced-contact scene, generated in code (every parameter is a member of ForcedScene, each
/// written in the scene note of experiment.md and in experiment.json, fixed and committed before
/// the first run of any response).
///
/// A cloth hangs folded over a bar: its four middle rows are fixed on a half-circle (the bar) and
/// the two halves hang down as a front layer (z = -r) and a back layer (z = +r). After the
/// cloth has settled, two grips take hold of a patch of each layer at the same place (a hand
/// pinching cloth, the seed's fig. 16: cloth pinched between limbs of an animated body that pass
/// through each other). They move the front patch through the back layer (+z) and the back patch
/// through the front layer (-z), so the layers must cross: a self-intersection that no response
/// can undo while the grips hold (gripped particles are kinematic: inverse mass 0). The grips hold
/// for H, then let go (the particles get their mass back, at rest) and the cloth is left to
/// itself for a horizon.
///
/// Why grips rather than pushing bodies: every obstacle of the engine pushes every particle, so a
/// body pushing one layer pushes the other ahead of it and never forces them through each other;
/// only something that holds each layer (the limbs' grip, by contact and friction, in the seed's
/// case) can.
///
/// The runs of an ensemble differ by a random offset of every free particle at the start
/// (uniform in a cube of side 2 x offset, from substream(seed, s)).
#include "core/cloth/self_collision_settings.h"
#include "comparisons/io/json_reader.h"
#include "core/scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tecido::suites::forced_contact {

struct ForcedScene {
  // Cloth (the same spring model as the seed's other scenes).
  int rows = 22;                 ///< along the folded length
  int cols = 10;                 ///< across the width
  double spacing = 0.1;          ///< [m]
  double total_mass = 1.89;      ///< [kg]: an interior particle carries 0.01 kg
  double stiffness = 8.0;        ///< [N/m], type A and type B springs
  double air_drag = 0.02;        ///< [kg/s] per particle (damping time m/c = 0.5 s)
  double dt = 0.01;              ///< [s], symplectic Euler
  // The bar: a half-circle of radius r at height y0, along x.
  double bar_height = 1.5;       ///< [m]
  double bar_radius = 0.1;       ///< [m]: the layers hang 2r = 0.2 m apart
  std::vector<int> bar_rows{9, 10, 11, 12};  ///< fixed rows (on the half-circle)
  // The grips.
  std::vector<int> front_rows{3, 4}, back_rows{17, 18}, grip_cols{4, 5};  ///< mirror images
  double settle = 1.5;           ///< [s] before the grips take hold
  double travel = 0.4;           ///< [m] each grip moves along z (front +z, back -z)
  double speed = 0.5;            ///< [m/s]
  // Responses.
  double strength = 0.05;        ///< [N] push of GIA and the edge modes (half a particle's weight)
  int impulse_iterations = 16;   ///< rounds of the impulse response per step
  // Perturbation.
  double offset = 0.01;          ///< [m] half side of the cube of a particle's initial offset
  std::uint64_t seed = 2016;     ///< base of the runs' substreams
};

/// Step numbers of the phases of one run with hold H.
struct Timeline {
  long long grip = 0;     ///< the step after which the grips take hold
  long long moved = 0;    ///< ... have travelled
  long long release = 0;  ///< ... let go (the first free step is release + 1)
  long long end = 0;      ///< the last step (the horizon)
};
Timeline timeline(const ForcedScene& f, double hold, double after_release);

/// The particles each grip holds (front grip first, then back) and its direction (+1 / -1 along z).
struct Grip {
  std::vector<int> particles;
  double direction = 1.0;
};
std::vector<Grip> grips(const ForcedScene& f);

/// The scene of run `s` of an ensemble with the given response: cloth folded on the bar,
/// perturbed by substream(f.seed, s); steps = timeline(...).end. GIA and the edge modes detect
/// discretely, the impulse response continuously.
Scene forced_scene(const ForcedScene& f, SelfCollisionResponse response, double hold, double after_release, int s);

/// The scene's parameters as JSON (experiment.json) and as a Markdown note (experiment.md).
io::Json scene_json(const ForcedScene& f);
std::string scene_note(const ForcedScene& f);

}  // namespace tecido::suites::forced_contact
