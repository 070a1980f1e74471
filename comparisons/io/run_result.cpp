#include "comparisons/io/run_result.h"

namespace tecido::io {

Json run_result_json(const Simulation& sim) {
  const auto& inst = sim.instability();
  Json particles = Json::array();
  const Particles& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    particles.push_back({{"x", {p.x[i].x(), p.x[i].y(), p.x[i].z()}}, {"v", {p.v[i].x(), p.v[i].y(), p.v[i].z()}}});
  }
  const ContactCounters& c = sim.contacts();
  Json out;
  out["status"] = inst ? "unstable" : "ok";
  out["unstable_at_step"] = inst ? Json(inst->step) : Json(nullptr);
  out["time"] = sim.time();
  out["steps"] = sim.steps_done();
  out["integrator"] = integrator_name(sim.scene().integrator);
  out["dt"] = sim.scene().dt;
  out["instability"] = inst ? Json{{"step", inst->step}, {"particle", inst->particle}, {"quantity", inst->quantity}}
                            : Json(nullptr);
  out["contacts"] = {{"events", c.events},
                     {"elastic", c.elastic},
                     {"static", c.static_contacts},
                     {"resting_now", sim.resting_contacts().size()},
                     {"bisections", c.bisections},
                     {"bisection_tolerance", sim.bisection_tolerance()},
                     {"event_cap_hits", c.cap_hits}};
  if (!sim.scene().obstacles.empty()) {
    const ObstacleCounters& o = sim.obstacle_contacts().counters();
    out["obstacles"] = {{"contacts", o.contacts},
                        {"separating", o.separating},
                        {"resting_now", sim.obstacle_contacts().resting().size()},
                        {"resting_corrections", o.resting_corrections},
                        {"guard_corrections", o.guard_corrections}};
  }
  out["particles"] = std::move(particles);
  return out;
}

}  // namespace tecido::io
