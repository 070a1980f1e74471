#include "comparisons/suites/obstacles/block_case.h"

#include "comparisons/suites/obstacles/block_scene.h"
#include "comparisons/suites/obstacles/cases.h"
#include "comparisons/suites/sweep.h"
#include "comparisons/view/run_view.h"
#include "core/simulation/simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tecido::suites::obstacles {

namespace {

/// Mean height above the top face of the particles over it, within 1 mm below it or higher.
double rest_height(const std::vector<Vec3>& x, const OrientedBox& b, const Vec3& up) {
  double sum = 0.0;
  int count = 0;
  for (const Vec3& p : x) {
    bool over = false;
    const double h = height_above_top(b, up, p, &over);
    if (over && h >= -1e-3) sum += h, ++count;
  }
  return count ? sum / count : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

io::Json block_case(const Settings& s, const std::string& data_dir, int n, bool edge_contacts) {
  const Scene sc = block_scene(s, data_dir, n, edge_contacts);
  const OrientedBox box = block_of(sc);
  const auto springs = stiff_springs(sc);
  Simulation sim(sc);
  sim.set_log_contacts(true);
  const long long steps = run_steps(s, sc);
  view::RunView page(sc);  // the run's page: the start and the counted frames
  page.add(0, sim.time(), sim.particles().x);
  io::Json frames = io::Json::array();
  int max_through = 0, end_through = 0, next_frame = 1;
  long long inside = 0;
  double max_spring_depth = 0.0, max_particle_depth = 0.0, end_depth = 0.0;
  for (long long k = 1; k <= steps && sim.step(); ++k) {
    const auto& x = sim.particles().x;
    double deepest = 0.0;
    const int through = springs_through_box(x, springs, box, s.through_depth, &deepest);
    max_through = std::max(max_through, through);
    end_through = through, end_depth = deepest;
    max_spring_depth = std::max(max_spring_depth, deepest);
    for (const Vec3& p : x) {
      const double d = point_box_depth(p, box);
      if (d > 0.0) ++inside, max_particle_depth = std::max(max_particle_depth, d);
    }
    if (k * s.block_frames >= next_frame * steps) {
      frames.push_back({num(sim.time()), through, num(deepest)});
      page.add(k, sim.time(), x);
      ++next_frame;
    }
  }
  const double t_onset = sim.contact_log().empty() ? std::numeric_limits<double>::quiet_NaN() : sim.contact_log().front().time;
  io::Json insets = io::Json::array();
  for (double f : edge_insets(sc)) insets.push_back(num(f));
  return {{"frames", frames},
          {"max_through", max_through},
          {"max_spring_depth", num(max_spring_depth)},
          {"steps_inside", inside},
          {"max_particle_depth", num(max_particle_depth)},
          {"t_onset", num(t_onset)},
          {"rest_height", num(rest_height(sim.particles().x, box, up_of(sc)))},
          {"springs", springs.size()},
          {"end_time", num(sim.time())},
          {"end_through", end_through},
          {"end_depth", num(end_depth)},
          {"spacing", num(sc.cloth->spacing)},
          {"insets", insets},
          {"across", springs_across_outline(sc)},
          {"unstable", sim.instability() ? io::Json(sim.instability()->step) : io::Json(nullptr)},
          {"view", page.data(block_name(n, edge_contacts))}};
}

}  // namespace tecido::suites::obstacles
