#include "comparisons/io/scene_to_json.h"

namespace tecido::io {

namespace {

Json vec(const Vec3& v) { return Json::array({v.x(), v.y(), v.z()}); }

Json particles_json(const Particles& p) {
  Json out = Json::array();
  for (std::size_t i = 0; i < p.size(); ++i) {
    Json q{{"position", vec(p.x[i])}, {"velocity", vec(p.v[i])}, {"elasticity", p.elasticity[i]}};
    if (p.pinned[i]) q["pinned"] = true;
    else q["mass"] = 1.0 / p.inv_mass[i];
    out.push_back(std::move(q));
  }
  return out;
}

Json springs_json(const std::vector<Spring>& springs) {
  Json out = Json::array();
  for (const Spring& s : springs) {
    Json j{{"i", s.i}, {"j", s.j}, {"stiffness", s.stiffness}, {"rest_length", s.rest_length}};
    if (s.damping != 0.0) j["damping"] = s.damping;
    out.push_back(std::move(j));
  }
  return out;
}

Json planes_json(const std::vector<BoundedPlane>& planes) {
  Json out = Json::array();
  for (const BoundedPlane& p : planes)
    out.push_back({{"position", vec(p.position)},
                   {"normal", vec(p.normal)},
                   {"forward", vec(p.forward)},
                   {"half_extents", Json::array({p.half_extents.x(), p.half_extents.y()})},
                   {"friction", p.friction}});
  return out;
}

Json wind_json(const Wind& w) {
  if (!w.swirl) return vec(w.force);
  return {{"force", vec(w.force)}, {"swirl", {{"rate", w.rate}, {"axis", vec(w.axis)}, {"phase", w.phase}}}};
}

}  // namespace

Json scene_to_json(const Scene& s) {
  Json j{{"integrator", integrator_name(s.integrator)}, {"dt", s.dt}, {"steps", s.steps}, {"seed", s.seed},
         {"particles", particles_json(s.particles)}};
  if (!s.forces.springs.empty()) j["springs"] = springs_json(s.forces.springs);
  if (s.forces.gravity) j["gravity"] = vec(*s.forces.gravity);
  if (s.forces.air_drag) j["air_drag"] = *s.forces.air_drag;
  if (s.forces.wind) j["wind"] = wind_json(*s.forces.wind);
  if (!s.planes.empty()) {
    j["planes"] = planes_json(s.planes);
    j["contact"] = {{"static_threshold", s.contact.static_threshold},
                    {"tangential_threshold", s.contact.tangential_threshold},
                    {"max_events_per_step", s.contact.max_events_per_step}};
    if (s.contact.bisection_tolerance > 0.0) j["contact"]["bisection_tolerance"] = s.contact.bisection_tolerance;  // 0: default
  }
  return j;
}

}  // namespace tecido::io
