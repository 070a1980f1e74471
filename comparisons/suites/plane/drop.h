#pragma once
/// The drop group of the `plane` suite: a particle released at rest at height z0 over the floor,
/// with restitution k, in core (bisected contact, midpoint) and, in a build with the reference
/// engines, in Bullet: a small rigid sphere (reference/bullet_rigid_drop.h) and a soft-body node
/// (the deformable twin, one node). Contact time and rebound apex against theory.h.
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/plane/settings.h"

#include <cmath>
#include <string>
#include <vector>

namespace tecido::suites::plane {

/// One height. Times in s, heights in m; NaN where an engine never touched the floor.
struct DropRow {
  double z0 = 0.0;
  double t_exact = 0.0, apex_exact = 0.0;  ///< sqrt(2 z0 / g) and k^2 z0
  double t_core = 0.0, apex_core = 0.0;    ///< apex: the highest step end after the contact
  bool bullet = false;                     ///< the Bullet columns were run (NaN otherwise)
  double t_rigid = NAN, apex_rigid = NAN;  ///< the sphere's lowest point
  double t_node = NAN, apex_node = NAN;    ///< first step end within the node's margin (+ slack)
  double node_margin = NAN;                ///< the twin's plane_contact_offset()
  std::vector<std::string> node_not_modelled;  ///< what the twin lists as not modelled for this scene
};

/// How long each engine runs: until into_fall of the first rebound's flight after t_exact [s].
double drop_duration(const DropSettings& s, double z0);

/// Runs the drop from z0 in core and in Bullet.
DropRow run_drop(const DropSettings& s, double z0);

io::Json drop_json(const DropRow& r);
DropRow drop_from_json(const io::Json& j);

}  // namespace tecido::suites::plane
