#include "comparisons/view/run_recording.h"

#include "comparisons/view/run_view.h"
#include "core/simulation/self_collision_response.h"
#include "core/simulation/simulation.h"

#include <algorithm>

namespace tecido::view {

io::Json record_run_page(const Scene& scene, long long every, const std::string& title) {
  every = std::max(1LL, every);
  Simulation sim(scene);
  const auto responder = install_self_collision(sim);  // none when the scene has no self_collision
  RunView page(scene);
  const long long stride = view_frame_stride(scene.steps, every, scene.particles.size());
  long long kept = 0;
  const auto capture = [&](const Simulation& s) {
    const long long k = s.steps_done();
    if ((k % every == 0 && kept++ % stride == 0) || k == scene.steps) page.add(k, s.time(), s.particles().x);
  };
  capture(sim);
  sim.run(scene.steps, capture);
  return page.data(title);
}

}  // namespace tecido::view
