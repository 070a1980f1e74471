#include "comparisons/suites/self_contact/interpretation.h"

#include <fmt/format.h>

namespace tecido::suites::self_contact {

io::Json interpretation_json(const Interpretation& in) {
  io::Json pins = io::Json::array();
  for (const auto& p : in.pins) pins.push_back({p[0], p[1]});
  return {{"elasticity_as", in.elasticity_as}, {"wind_per", in.wind_per},
          {"strength", in.strength},           {"air_drag", in.air_drag},
          {"swirl_rate", in.swirl_rate},       {"heading_diffusion", in.heading_diffusion},
          {"pins", pins}};
}

Interpretation interpretation_from_json(const io::Json& j) {
  Interpretation in;
  in.elasticity_as = j.at("elasticity_as").get<std::string>();
  in.wind_per = j.at("wind_per").get<std::string>();
  in.strength = j.at("strength").get<double>();
  in.air_drag = j.at("air_drag").get<double>();
  in.swirl_rate = j.at("swirl_rate").get<double>();
  in.heading_diffusion = j.at("heading_diffusion").get<double>();
  for (const auto& p : j.at("pins")) in.pins.push_back({p.at(0).get<int>(), p.at(1).get<int>()});
  return in;
}

std::string describe(const Interpretation& in) {
  std::string pins;
  for (const auto& p : in.pins) pins += fmt::format(" ({},{})", p[0], p[1]);
  return fmt::format(
      "elasticity as {}, wind per {}, push {:g} N, air drag {:g} kg/s, swirl {:g} rad/s, heading diffusion {:g} "
      "rad^2/s, pins{}",
      in.elasticity_as, in.wind_per, in.strength, in.air_drag, in.swirl_rate, in.heading_diffusion, pins);
}

}  // namespace tecido::suites::self_contact
