#include "comparisons/suites/obstacles/fcl_cases.h"

#include "comparisons/suites/obstacles/block_scene.h"
#include "comparisons/suites/obstacles/theory.h"
#include "comparisons/suites/sweep.h"
#include "core/simulation/simulation.h"
#include "core/geometry/box_mesh.h"
#include "core/geometry/ccd/query.h"
#include "reference/fcl_adapter.h"

#include <cmath>
#include <limits>

namespace tecido::suites::obstacles {

namespace {

/// The earliest toi in [0, 1] of any vertex path x0[i] -> x1[i] against the static triangles, or NaN.
double earliest_toi(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, const std::array<Vec3, 8>& corners) {
  double best = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < x0.size(); ++i)
    for (const auto& t : kBoxTriangles) {
      CcdQuery q;
      q.kind = CcdKind::VertexFace;
      q.x0 = {corners[t[0]], corners[t[1]], corners[t[2]], x0[i]};
      q.x1 = {corners[t[0]], corners[t[1]], corners[t[2]], x1[i]};
      const CcdAnswer a = reference::fcl_ccd(q);
      if (a.hit && !(a.toi >= best)) best = a.toi;
    }
  return best;
}

}  // namespace

io::Json fcl_block_case(const Settings& s, const std::string& data_dir, int n) {
  const Scene with_block = block_scene(s, data_dir, n, false);
  Scene free_fall = with_block;
  free_fall.obstacles.clear();
  const OrientedBox box = block_of(with_block);
  std::array<Vec3, 8> corners = box_corners(box.half);
  for (Vec3& c : corners) c = box.center + box.rotation * c;
  Simulation fall(free_fall);
  double t_fcl = std::numeric_limits<double>::quiet_NaN();
  const long long steps = run_steps(s, with_block);
  for (long long k = 0; k < steps && std::isnan(t_fcl); ++k) {
    const std::vector<Vec3> x0 = fall.particles().x;
    const double t0 = fall.time();
    if (!fall.step()) break;
    const double toi = earliest_toi(x0, fall.particles().x, corners);
    if (!std::isnan(toi)) t_fcl = t0 + toi * with_block.dt;
  }
  Simulation core(with_block);
  core.set_log_contacts(true);
  for (long long k = 0; k < steps && core.contact_log().empty() && core.step(); ++k) {
  }
  const double t_core = core.contact_log().empty() ? std::numeric_limits<double>::quiet_NaN() : core.contact_log().front().time;
  return {{"t_fcl", num(t_fcl)}, {"t_core", num(t_core)}, {"t_exact", num(fall_time(initial_gap(with_block), with_block.forces.gravity.value_or(Vec3::Zero()).norm()))},
          {"dt", num(with_block.dt)}};
}

}  // namespace tecido::suites::obstacles
