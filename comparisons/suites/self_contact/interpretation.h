#pragma once
/// A reading of the seed's experiment: every choice the seed leaves open, as numbers (docs of
/// each choice: data/scenes/seed_fig21_self_contact.json, beside the value it sets).
///  - elasticity_as: what the cloth's "elasticidade" (0.9, 0.5) is. "stiffness": the springs'
///    stiffness quotient ks (the file's stiffness_b and stiffness_a are e = 1 and are multiplied
///    by e; the seed calls ks "o quociente de elasticidade do tecido", 3.1.2); "restitution": the
///    particles' restitution quotient k (acts only in plane contacts: none in this scene);
///  - wind_per: the wind's 0.09 / 0.1 / 0.11 N on every free particle ("particle") or in total,
///    split equally over the free particles ("total");
///  - strength: the edge modes' push per particle [N] (the seed gives none);
///  - air_drag [kg/s] and swirl_rate [rad/s]: calibrated (calibration.h);
///  - heading_diffusion [rad^2/s]: how randomly the wind wanders (core/dynamics/random_wind.h);
///  - pins: the six held nodes (row, col).
#include "comparisons/io/json_reader.h"

#include <array>
#include <string>
#include <vector>

namespace tecido::suites::self_contact {

struct Interpretation {
  std::string elasticity_as = "stiffness";  ///< "stiffness" | "restitution"
  std::string wind_per = "particle";        ///< "particle" | "total"
  double strength = 0.0;
  double air_drag = 0.0;
  double swirl_rate = 0.0;
  double heading_diffusion = 0.0;
  std::vector<std::array<int, 2>> pins;
};

/// As JSON {"elasticity_as","wind_per","strength","air_drag","swirl_rate","heading_diffusion","pins"},
/// and back (throws nlohmann exceptions on a malformed object).
io::Json interpretation_json(const Interpretation& in);
Interpretation interpretation_from_json(const io::Json& j);

/// "e as stiffness, wind per particle, push 0.05 N, drag 0.02 kg/s, swirl 0.7 rad/s, heading
/// diffusion 0.1 rad^2/s, pins (0,0) (0,3) ..." for reports.
std::string describe(const Interpretation& in);

}  // namespace tecido::suites::self_contact
