#include "comparisons/suites/stability/tunnelling.h"

#include "core/simulation/simulation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tecido::suites::stability {

namespace {

const IntegratorKind kAll[] = {IntegratorKind::Euler, IntegratorKind::Symplectic, IntegratorKind::Midpoint,
                               IntegratorKind::RK4};

struct Fall {
  long long wrong = 0;  ///< steps that ended below the plane
  double zmin = 0.0;
  long long contacts = 0;
  long long unstable_step = 0;
};

Fall run_fall(const TunnellingSettings& t, IntegratorKind k, double speed, double dt) {
  Scene s;
  s.integrator = k;
  s.dt = dt;
  s.forces.gravity = Vec3(0, 0, -9.81);
  s.particles.add(Vec3(0.1, 0.2, 1.0), Vec3(0, 0, -speed), 1.0, 0.5, false);
  s.planes.push_back(make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), Vec2(0.5, 0.5), 0.5));
  Simulation sim(s);
  const long long n = std::max<long long>(t.min_steps, std::llround(t.duration / dt));
  Fall f;
  f.zmin = INFINITY;
  for (long long i = 0; i < n; ++i) {
    if (!sim.step()) {
      f.unstable_step = sim.instability()->step;
      break;
    }
    const double z = sim.particles().x[0].z();
    f.zmin = std::min(f.zmin, z);
    if (z < 0.0) ++f.wrong;
  }
  f.contacts = sim.contacts().events;
  return f;
}

/// One (speed, dt): every integrator; its wrong-side steps add to data["tunnelling"], an unstable
/// run marks `wrong` missing.
void fall_row(const TunnellingSettings& t, double speed, double dt, ValueRange& wrong, ExtremeResult& res) {
  std::string measured;
  long long wrong_row = 0;
  bool broke = false;
  for (IntegratorKind k : kAll) {
    const Fall f = run_fall(t, k, speed, dt);
    const std::string label = fmt::format("{}, dt = {:g} s, {:g} m/s", integrator_name(k), dt, speed);
    if (f.unstable_step) {
      wrong.missing(fmt::format("unstable at step {} ({})", f.unstable_step, label));
      broke = true;
    }
    wrong_row += f.wrong;
    measured += fmt::format("{}{}: {} wrong-side steps, min z {}, {} contacts{}", measured.empty() ? "" : "; ",
                            integrator_name(k), f.wrong, sci(f.zmin), f.contacts,
                            f.unstable_step ? fmt::format(", unstable at step {}", f.unstable_step) : "");
  }
  io::Json& d = res.data["tunnelling"];
  d["wrong_side_steps"] = d["wrong_side_steps"].get<long long>() + wrong_row;
  d["runs"] = d["runs"].get<long long>() + static_cast<long long>(std::size(kAll));
  d["max_dt"] = std::max(d["max_dt"].get<double>(), dt);
  res.rows.push_back({"tunnelling", fmt::format("dt = {:g} s, falling at {:g} m/s from 1 m, {:g} s", dt, speed, t.duration),
                      measured,
                      broke ? "broke: non-finite" : (wrong_row == 0 ? "ok: never on the wrong side" : "broke: tunnelled"),
                      {}});
}

}  // namespace

std::vector<CheckSpec> tunnelling_checks(const Settings& s) {
  const double max_dt = s.tunnelling.dts.empty() ? 0.0 : *std::max_element(s.tunnelling.dts.begin(), s.tunnelling.dts.end());
  return {{extremes_check("tunnel_wrong_side_steps"),
           [](const Tolerances& t) { return t.at_most("/stability/tunnel_wrong_side_steps"); },
           fmt::format("steps ending below a thin plane, any dt up to {:g} s, any integrator", max_dt)}};
}

ExtremeResult run_tunnelling(const Settings& s) {
  ExtremeResult res;
  res.data["tunnelling"] = {{"wrong_side_steps", 0LL}, {"runs", 0LL}, {"max_dt", 0.0}};
  ValueRange wrong;
  for (double speed : s.tunnelling.speeds)
    for (double dt : s.tunnelling.dts) fall_row(s.tunnelling, speed, dt, wrong, res);
  const double total = static_cast<double>(res.data["tunnelling"]["wrong_side_steps"].get<long long>());
  wrong.add(total, "all runs");
  res.from_range(extremes_check("tunnel_wrong_side_steps"), wrong, total);
  return res;
}

}  // namespace tecido::suites::stability
