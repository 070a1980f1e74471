#include "comparisons/engines/outside/process_simulation.h"

#include <cmath>

namespace tecido::outside {

ProcessSimulation::ProcessSimulation(std::shared_ptr<ProcessEngine> engine, const Scene& scene)
    : engine_(std::move(engine)), dt_(scene.dt), x_(scene.particles.x), v_(scene.particles.v) {}

ProcessSimulation::~ProcessSimulation() { engine_->release_scene(); }

bool ProcessSimulation::advance(long long n) {
  if (failed_) return false;
  if (n <= 0) return true;
  const io::Json reply = engine_->request(step_request(dt_, n), "step");
  State s;
  try {
    s = parse_step(reply, x_.size());
  } catch (const ProtocolError& p) {
    engine_->fail("step", p.what());
  }
  x_ = std::move(s.x);
  v_ = std::move(s.v);
  steps_ += n;
  for (std::size_t i = 0; i < x_.size() && !failed_; ++i) failed_ = !x_[i].allFinite() || !v_[i].allFinite();
  return !failed_;
}

}  // namespace tecido::outside
