#include "comparisons/suites/self_contact/sensitivity.h"

#include <fmt/format.h>

#include <map>

namespace tecido::suites::self_contact {

namespace {

Variant scaled(const Interpretation& base, const char* id, const char* choice, double Interpretation::*field,
               double factor, const char* unit) {
  Variant v{id, choice, "", base, false};
  v.in.*field *= factor;
  v.about = fmt::format("{:g}x: {:g} {}", factor, v.in.*field, unit);
  return v;
}

}  // namespace

bool is_sensitivity_set(const std::string& name) { return name == "none" || name == "strength" || name == "all"; }

std::vector<Variant> variants(const Interpretation& baseline, const ClothGridSpec& cloth, const std::string& which) {
  std::vector<Variant> out{{"baseline", "none", "the baseline reading", baseline, false}};
  if (which == "none") return out;
  Variant push_low = scaled(baseline, "push-0.4x", "push strength", &Interpretation::strength, 0.4, "N");
  Variant push_high = scaled(baseline, "push-2x", "push strength", &Interpretation::strength, 2.0, "N");
  push_low.reuses_none = push_high.reuses_none = true;
  if (which == "strength") {
    out.push_back(push_low);
    out.push_back(push_high);
    return out;
  }
  Variant v{"elasticity-restitution", "elasticity", "the particles' restitution quotient (springs as in the file)", baseline,
            false};
  v.in.elasticity_as = "restitution";
  out.push_back(v);
  v = {"wind-total", "wind", "the force in total, split over the free particles", baseline, false};
  v.in.wind_per = "total";
  out.push_back(v);
  out.push_back(push_low);
  out.push_back(push_high);
  out.push_back(scaled(baseline, "swirl-0.5x", "swirl rate", &Interpretation::swirl_rate, 0.5, "rad/s"));
  out.push_back(scaled(baseline, "swirl-2x", "swirl rate", &Interpretation::swirl_rate, 2.0, "rad/s"));
  out.push_back(scaled(baseline, "drag-0.5x", "air drag", &Interpretation::air_drag, 0.5, "kg/s"));
  out.push_back(scaled(baseline, "drag-2x", "air drag", &Interpretation::air_drag, 2.0, "kg/s"));
  out.push_back(scaled(baseline, "diffusion-0", "wind randomness", &Interpretation::heading_diffusion, 0.0, "rad^2/s"));
  out.push_back(scaled(baseline, "diffusion-4x", "wind randomness", &Interpretation::heading_diffusion, 4.0, "rad^2/s"));
  const int last = cloth.cols - 1;
  v = {"pins-corners", "pins", "hung by its two top corners, three nodes each (fig. 14: \"pendurado pelas pontas\")", baseline,
       false};
  v.in.pins = {{0, 0}, {0, 1}, {1, 0}, {0, last}, {0, last - 1}, {1, last}};
  out.push_back(v);
  return out;
}

std::vector<Robustness> robustness(const std::vector<SensitivityRow>& rows) {
  std::vector<Robustness> out;
  std::map<std::string, std::size_t> at;
  for (const SensitivityRow& row : rows)
    for (const Claim& c : row.claims) {
      if (!at.count(c.id)) {
        at[c.id] = out.size();
        out.push_back({c.id, "", 0, 0, 0});
      }
      Robustness& r = out[at[c.id]];
      r.reproduced += c.verdict == Verdict::Reproduced;
      r.not_reproduced += c.verdict == Verdict::NotReproduced;
      r.inconclusive += c.verdict == Verdict::Inconclusive;
    }
  for (Robustness& r : out) {
    const int kinds = (r.reproduced > 0) + (r.not_reproduced > 0) + (r.inconclusive > 0);
    r.status = kinds == 1 ? "robust" : (r.reproduced > 0 && r.not_reproduced > 0) ? "fragile" : "unsettled";
  }
  return out;
}

}  // namespace tecido::suites::self_contact
