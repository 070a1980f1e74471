#include "comparisons/suites/self_contact/run.h"

#include "core/cloth/gia.h"
#include "core/simulation/self_collision_response.h"
#include "core/simulation/simulation.h"

#include <limits>
#include <memory>

namespace tecido::suites::self_contact {

namespace {

/// The premise's questions about one frame's exact contacts.
void analyse_premise(const Simulation& sim, const SelfCollisionResponder& responder, GiaResult& gia,
                     PremiseCount& out) {
  const auto& pairs = responder.last_pairs();
  if (pairs.empty()) return;
  ++out.contact_frames;
  const auto& tris = sim.scene().triangles;
  const MeshTopology& topo = responder.topology();
  bool border = false;
  for (const TrianglePair& p : pairs)
    for (int t : p)
      for (int v : tris[t]) border = border || topo.border_distance[v] == 0;
  out.border_frames += border;
  analyse_intersections(sim.particles().x, tris, topo, pairs, gia);
  out.unresolved_frames += gia.unresolved_pairs > 0;
  out.unseparated_frames += gia.unseparated_cut_edges > 0;
}

}  // namespace

RunResult run_scene(const Scene& scene, const std::vector<ContactTest>& detectors, bool premise) {
  Simulation sim(scene);
  const std::shared_ptr<SelfCollisionResponder> responder = install_self_collision(sim);
  std::vector<std::unique_ptr<SelfContactCounter>> counters;
  for (ContactTest t : detectors) counters.push_back(std::make_unique<SelfContactCounter>(scene.triangles, sim.particles().x, t));
  RunResult r;
  GiaResult gia;
  sim.post_step = [&](Simulation& s) {
    (*responder)(s);  // exact detection and the scene's response (velocities only)
    for (auto& c : counters) {
      if (c->test() == ContactTest::Core) {
        c->count_pairs(responder->last_pairs().size());
      } else {
        c->count(s.particles().x);
      }
    }
    if (premise) analyse_premise(s, *responder, gia, r.premise);
  };
  sim.run(scene.steps);
  for (const auto& c : counters) r.counts.push_back(c->counts());
  if (sim.instability()) {
    r.status = "unstable";
    r.unstable_at_step = sim.instability()->step;
  }
  return r;
}

io::Json run_json(const RunResult& r, bool premise) {
  io::Json counts = io::Json::array();
  for (const SelfContactCount& c : r.counts) counts.push_back({c.frames, c.contact_frames, c.pairs, c.max_pairs});
  io::Json j = {{"status", r.status},
                {"unstable_at_step", r.unstable_at_step >= 0 ? io::Json(r.unstable_at_step) : io::Json(nullptr)},
                {"counts", counts}};
  if (premise) {
    const PremiseCount& p = r.premise;
    j["premise"] = {p.contact_frames, p.border_frames, p.unresolved_frames, p.unseparated_frames};
  }
  return j;
}

RunResult run_from_json(const io::Json& j) {
  RunResult r;
  r.status = j.at("status").get<std::string>();
  r.unstable_at_step = j.at("unstable_at_step").is_null() ? -1 : j.at("unstable_at_step").get<long long>();
  for (const auto& c : j.at("counts")) {
    SelfContactCount k;
    k.frames = c.at(0).get<long long>();
    k.contact_frames = c.at(1).get<long long>();
    k.pairs = c.at(2).get<long long>();
    k.max_pairs = c.at(3).get<long long>();
    r.counts.push_back(k);
  }
  if (j.contains("premise")) {
    const auto& p = j.at("premise");
    r.premise = {p.at(0).get<long long>(), p.at(1).get<long long>(), p.at(2).get<long long>(), p.at(3).get<long long>()};
  }
  return r;
}

double share(const RunResult& r, std::size_t d) {
  const SelfContactCount& c = r.counts.at(d);
  if (c.frames == 0) return std::numeric_limits<double>::quiet_NaN();
  return static_cast<double>(c.contact_frames) / static_cast<double>(c.frames);
}

}  // namespace tecido::suites::self_contact
