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
  if (sim.scene().edge_contacts && !sim.scene().obstacles.empty()) {
    const SpringBoxCounters& b = sim.spring_box_contacts().counters();
    const EdgeCounters& e = sim.edge_contacts().counters();
    out["edge_contacts"] = {{"spring_box", {{"contacts", b.contacts},
                                            {"separating", b.separating},
                                            {"moved_out", b.moved_out},
                                            {"unresolved", b.unresolved},
                                            {"resting_now", sim.spring_box_contacts().resting_count()}}},
                            {"spring_edge", {{"contacts", e.contacts},
                                             {"separating", e.separating},
                                             {"resting_corrections", e.resting_corrections},
                                             {"moved_through", e.moved_through},
                                             {"resting_now", sim.edge_contacts().resting_count()}}}};
  }
  out["particles"] = std::move(particles);
  return out;
}

io::Json self_collision_json(const SelfCollisionResponder& r) {
  const SelfCollisionStats& st = r.stats();
  return {{"response", self_collision_response_name(r.settings().response)},
          {"checks", st.checks},
          {"contact_checks", st.contact_checks},
          {"share", st.checks ? static_cast<double>(st.contact_checks) / st.checks : 0.0},
          {"pairs", st.pairs},
          {"max_pairs", st.max_pairs},
          {"pairs_now", st.last_pairs},
          {"gia_regions", st.gia_regions},
          {"gia_failed_checks", st.gia_failed_checks},
          {"gia_unresolved_pairs", st.gia_unresolved_pairs},
          {"unseparated_cut_edges", st.unseparated_cut_edges},
          {"pushed_particles", st.pushed_particles}};
}

}  // namespace tecido::io
