#include "comparisons/engines/outside/process_simulation.h"

namespace tecido::outside {

ProcessSimulation::ProcessSimulation(std::shared_ptr<ProcessEngine> engine, const Scene& scene)
    : SteppedSimulation(scene.dt), engine_(std::move(engine)) {
  begin(scene.particles.x, scene.particles.v);
}

ProcessSimulation::~ProcessSimulation() { engine_->release_scene(); }

bool ProcessSimulation::call_step(long long n) {
  const io::Json reply = engine_->request(step_request(dt(), n), "step");
  State s;
  try {
    s = parse_step(reply, x_.size());
  } catch (const ProtocolError& p) {
    engine_->fail("step", p.what());
  }
  x_ = std::move(s.x);
  v_ = std::move(s.v);
  return true;
}

}  // namespace tecido::outside
