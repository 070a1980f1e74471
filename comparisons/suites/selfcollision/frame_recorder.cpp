#include "comparisons/suites/selfcollision/frame_recorder.h"

#include "core/cloth/self_collision.h"
#include "core/simulation/simulation.h"

#include <cmath>

namespace tecido::suites::selfcollision {

FrameSet record_frames(const Scene& scene, long long steps, long long every, int count, double contact_share) {
  FrameSet out;
  out.triangles = scene.triangles;
  Simulation sim(scene);
  SelfCollisionDetector det(scene.triangles, scene.particles.x);
  const int want_with = static_cast<int>(std::lround(count * contact_share));
  int with = 0, without = 0;
  for (long long i = 1; i <= steps && with + without < count; ++i) {
    if (!sim.step()) break;
    if (i % every) continue;
    const bool contact = !det.detect(sim.particles().x).empty();
    if (contact ? with < want_with : without < count - want_with) {
      (contact ? with : without)++;
      out.frames.push_back(Frame{sim.time(), sim.particles().x});
    }
  }
  return out;
}

}  // namespace tecido::suites::selfcollision
