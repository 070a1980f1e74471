#include "comparisons/suites/forced_contact/run.h"

#include "comparisons/suites/sweep.h"
#include "core/cloth/self_contact_counter.h"
#include "core/simulation/self_collision_response.h"
#include "core/simulation/simulation.h"

#include <cmath>
#include <memory>

namespace tecido::suites::forced_contact {

namespace {

/// The grips' state in a run: where each held particle was taken, and its mass to give back.
class Grips {
 public:
  Grips(const ForcedScene& f, const Timeline& t) : f_(f), t_(t), grips_(grips(f)) {}

  /// Moves the held particles for the state after step k (called after every step).
  void apply(long long k, Particles& p) {
    if (k < t_.grip || k > t_.release) return;
    if (k == t_.grip) take(p);
    const bool release = k == t_.release;
    const double moved = std::min(static_cast<double>(k - t_.grip) * f_.dt * f_.speed, f_.travel);
    const bool moving = k < t_.moved;
    std::size_t n = 0;
    for (const Grip& g : grips_)
      for (int i : g.particles) {
        p.x[i] = start_[n] + Vec3(0.0, 0.0, g.direction * moved);
        p.v[i] = release || !moving ? Vec3::Zero() : Vec3(0.0, 0.0, g.direction * f_.speed);
        if (release) {
          p.inv_mass[i] = inv_mass_[n];
          p.pinned[i] = 0;
        }
        ++n;
      }
  }

 private:
  void take(Particles& p) {
    for (const Grip& g : grips_)
      for (int i : g.particles) {
        start_.push_back(p.x[i]);
        inv_mass_.push_back(p.inv_mass[i]);
        p.inv_mass[i] = 0.0;
        p.pinned[i] = 1;
      }
  }

  const ForcedScene& f_;
  Timeline t_;
  std::vector<Grip> grips_;
  std::vector<Vec3> start_;
  std::vector<double> inv_mass_;
};

}  // namespace

void decide_recovery(const std::vector<long long>& after, double dt, const Settings& s, RunResult& r) {
  std::size_t first_free = after.size();  // the first frame of the final free stretch
  while (first_free > 0 && after[first_free - 1] == 0) --first_free;
  r.free_at_end = !after.empty() && after.back() == 0;
  const double start = static_cast<double>(first_free + 1) * dt;
  r.recovered = first_free < after.size() && start <= censor_time(s) + 1e-9 * dt;
  r.recovery = r.recovered ? start : 0.0;
}

RunResult run_forced(const ForcedScene& f, const Settings& s, SelfCollisionResponse response, double hold, int seed,
                     const FrameFn& on_frame) {
  const Scene scene = forced_scene(f, response, hold, s.after_release, seed);
  const Timeline t = timeline(f, hold, s.after_release);
  const long long every = std::max(1LL, std::llround(s.sample / f.dt));
  Simulation sim(scene);
  const std::shared_ptr<SelfCollisionResponder> responder = install_self_collision(sim);
  SelfContactCounter counter(scene.triangles, sim.particles().x, ContactTest::Core);
  Grips held(f, t);
  RunResult r;
  std::vector<long long> after;
  sim.post_step = [&](Simulation& sm) {
    const long long k = sm.steps_done();
    held.apply(k, sm.mutable_particles());
    (*responder)(sm);
    const auto pairs = static_cast<long long>(counter.count(sm.particles().x).size());
    if (k > t.grip && k <= t.release) r.hold_max_pairs = std::max(r.hold_max_pairs, pairs);
    if (k == t.release) r.held_pairs = pairs;  // counted before the grips let go (next step)
    if (k > t.release) after.push_back(pairs);
    if (k % every == 0) r.series.push_back(pairs);
    if (on_frame) on_frame(k, scene, sm.particles().x);
  };
  sim.run(scene.steps);
  if (sim.instability()) {
    r.status = "unstable";
    r.unstable_at_step = sim.instability()->step;
    return r;
  }
  decide_recovery(after, f.dt, s, r);
  return r;
}

io::Json run_json(const RunResult& r) {
  return {{"status", r.status},
          {"unstable_at_step", r.unstable_at_step >= 0 ? io::Json(r.unstable_at_step) : io::Json(nullptr)},
          {"series", r.series},
          {"held_pairs", r.held_pairs},
          {"hold_max_pairs", r.hold_max_pairs},
          {"recovered", r.recovered},
          {"recovery", num(r.recovery)},
          {"free_at_end", r.free_at_end}};
}

RunResult run_from_json(const io::Json& j) {
  RunResult r;
  r.status = j.at("status").get<std::string>();
  r.unstable_at_step = j.at("unstable_at_step").is_null() ? -1 : j.at("unstable_at_step").get<long long>();
  r.series = j.at("series").get<std::vector<long long>>();
  r.held_pairs = j.at("held_pairs").get<long long>();
  r.hold_max_pairs = j.at("hold_max_pairs").get<long long>();
  r.recovered = j.at("recovered").get<bool>();
  r.recovery = get_num(j.at("recovery"));
  r.free_at_end = j.at("free_at_end").get<bool>();
  return r;
}

}  // namespace tecido::suites::forced_contact
