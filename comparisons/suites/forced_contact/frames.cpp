#include "comparisons/suites/forced_contact/frames.h"

#include "comparisons/io/frame_writer.h"

#include <fmt/format.h>

#include <cmath>

namespace tecido::suites::forced_contact {

long long write_frames(const Plan& plan, const std::string& dir) {
  const Settings& s = plan.settings;
  const long long every = std::max(1LL, std::llround(s.sample / plan.scene.dt));
  long long written = 0;
  for (std::size_t h = 0; h < s.holds.size(); ++h)
    for (SelfCollisionResponse r : s.responses) {
      io::FrameWriter w(fmt::format("{}/frames/{}-hold{}", dir, self_collision_response_name(r), s.holds[h]), true, false);
      const FrameFn on_frame = [&](long long step, const Scene& scene, const std::vector<Vec3>& x) {
        if (step % every == 0) w.write(step, static_cast<double>(step) * scene.dt, x, {}, scene.triangles);
      };
      run_forced(plan.scene, s, r, s.holds[h], 0, on_frame);
      written += w.written();
    }
  return written;
}

}  // namespace tecido::suites::forced_contact
