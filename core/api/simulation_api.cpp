// The public Simulation of include/tecido/simulation.h: core's Simulation with the self-collision
// hook installed, as `tecido run` builds it (comparisons/cli/cmd_run.cpp), and its state read out.
#include "core/api/scene_access.h"
#include "core/geometry/obstacle_start.h"
#include "core/simulation/self_collision_response.h"
#include "core/simulation/simulation.h"

#include <stdexcept>
#include <string>

namespace tecido::core {

namespace detail {

struct SimulationData {
  explicit SimulationData(const ::tecido::Scene& scene) : sim(scene), self_collision(install_self_collision(sim)) {}
  ::tecido::Simulation sim;
  std::shared_ptr<SelfCollisionResponder> self_collision;
  std::optional<Divergence> divergence;

  /// After a step or a run: false once diverged (also for a run of 0 steps after divergence).
  bool record() {
    if (!divergence && sim.instability()) {
      const Instability& i = *sim.instability();
      divergence = Divergence{i.step, i.particle, i.quantity};
    }
    return !divergence;
  }
};

}  // namespace detail

namespace {

/// The scene, refused when no simulation can start from it.
const ::tecido::Scene& startable(const Scene& scene) {
  const ::tecido::Scene& s = detail::SceneAccess::scene(scene);
  if (s.particles.size() == 0) throw std::invalid_argument("tecido::core::Simulation: the scene has no particles");
  for (std::size_t k = 0; k < s.obstacles.size(); ++k) {
    const int i = first_free_particle_inside(s.obstacles[k], s.particles.x, s.particles.pinned);
    if (i >= 0)
      throw std::invalid_argument("tecido::core::Simulation: free particle " + std::to_string(i) + " starts inside " +
                                  obstacle_kind_name(s.obstacles[k].kind) + " " + std::to_string(k) +
                                  " (spheres and boxes are solid)");
  }
  return s;
}

}  // namespace

Simulation::Simulation(const Scene& scene) : d_(std::make_unique<detail::SimulationData>(startable(scene))) {}
Simulation::~Simulation() = default;
Simulation::Simulation(Simulation&& other) noexcept = default;
Simulation& Simulation::operator=(Simulation&& other) noexcept = default;

bool Simulation::step() {
  d_->sim.step();
  return d_->record();
}

bool Simulation::run(long long steps) {
  if (steps < 0) throw std::invalid_argument("tecido::core::Simulation::run: steps must be >= 0, got " + std::to_string(steps));
  d_->sim.run(steps);
  return d_->record();
}

const std::vector<Vec3>& Simulation::positions() const { return d_->sim.particles().x; }
const std::vector<Vec3>& Simulation::velocities() const { return d_->sim.particles().v; }
double Simulation::time() const { return d_->sim.time(); }
long long Simulation::steps_done() const { return d_->sim.steps_done(); }
const std::optional<Divergence>& Simulation::divergence() const { return d_->divergence; }

ContactCounts Simulation::contacts() const {
  const ContactCounters& c = d_->sim.contacts();
  ContactCounts out;
  out.events = c.events;
  out.elastic = c.elastic;
  out.static_contacts = c.static_contacts;
  out.bisections = c.bisections;
  out.event_cap_hits = c.cap_hits;
  out.resting_now = d_->sim.resting_contacts().size();
  out.obstacle_contacts = d_->sim.obstacle_contacts().counters().contacts;
  return out;
}

SelfCollisionCounts Simulation::self_collision() const {
  SelfCollisionCounts out;
  if (!d_->self_collision) return out;
  const SelfCollisionStats& s = d_->self_collision->stats();
  out.checks = s.checks;
  out.contact_checks = s.contact_checks;
  out.pairs = s.pairs;
  out.pairs_now = s.last_pairs;
  return out;
}

}  // namespace tecido::core
