#include "comparisons/suites/stability/resting.h"

#include "core/simulation/simulation.h"

#include <fmt/format.h>

#include <algorithm>

namespace tecido::suites::stability {

namespace {

struct Rest {
  double sink = 0.0, height = 0.0, vmax = 0.0, drift = 0.0;
  long long unstable_step = 0;
  bool resting = false;  ///< in resting contact at the end
};

/// A particle released on a 2 m x 2 m plane (k = 0.5, friction 0.5) at `offset` on every axis.
Rest run_rest(const RestingSettings& r, IntegratorKind k, double offset) {
  const double O = offset;
  Scene s;
  s.integrator = k;
  s.dt = r.dt;
  s.forces.gravity = Vec3(0, 0, -9.81);
  s.particles.add(Vec3(O + 0.1, O + 0.2, O), Vec3::Zero(), 1.0, 0.5, false);
  s.planes.push_back(make_bounded_plane(Vec3(O, O, O), Vec3::UnitZ(), Vec3::UnitX(), Vec2(1.0, 1.0), 0.5));
  Simulation sim(s);
  Rest out;
  for (long long i = 0; i < r.steps; ++i) {
    if (!sim.step()) {
      out.unstable_step = sim.instability()->step;
      return out;
    }
    const double z = s.planes[0].side(sim.particles().x[0]);
    out.sink = std::max(out.sink, -z);
    out.height = std::max(out.height, z);
    out.vmax = std::max(out.vmax, sim.particles().v[0].norm());
  }
  out.drift = (sim.particles().x[0] - s.particles.x[0]).norm();
  out.resting = !sim.resting_contacts().empty();
  return out;
}

void rest_row(const RestingSettings& r, IntegratorKind k, double offset, ValueRange& sink, ValueRange& height,
              ExtremeResult& res) {
  const Rest x = run_rest(r, k, offset);
  const std::string label = fmt::format("{}, at rest on a plane{}, {} steps of {:g} s", integrator_name(k),
                                        offset != 0.0 ? fmt::format(" at {:g} m", offset) : "", r.steps, r.dt);
  if (x.unstable_step) {
    const std::string why = fmt::format("unstable at step {} ({})", x.unstable_step, label);
    sink.missing(why);
    height.missing(why);
    res.rows.push_back({"resting contact", label, fmt::format("unstable at step {}", x.unstable_step), "broke: non-finite", {}});
    return;
  }
  sink.add(x.sink, label);
  height.add(x.height, label);
  io::Json& d = res.data["resting"];
  d["max_speed"] = std::max(d["max_speed"].get<double>(), x.vmax);
  d["max_drift"] = std::max(d["max_drift"].get<double>(), x.drift);
  const std::string measured =
      fmt::format("max sink {} m, max height above {} m, max |v| {} m/s, drift {} m, resting: {}", sci(x.sink),
                  sci(x.height), sci(x.vmax), sci(x.drift), x.resting ? "yes" : "no");
  if (x.sink > 0.0) {
    res.rows.push_back({"resting contact", label, measured, "broke: sank below the plane", {}});
  } else {
    res.rows.push_back({"resting contact", label, measured, "",
                        ExtremeRow::Judge{"rest_jitter", {x.height}, "ok: still", "degraded: jitters above the plane"}});
  }
}

}  // namespace

std::vector<CheckSpec> resting_checks(const Settings& s) {
  const std::string over = fmt::format("over {} resting steps, any integrator", s.resting.steps);
  return {{extremes_check("rest_max_sink"), [](const Tolerances& t) { return t.at_most("/stability/rest_max_sink"); },
           "max depth below the plane " + over},
          {extremes_check("rest_max_jitter"), [](const Tolerances& t) { return t.at_most("/stability/rest_max_jitter"); },
           "max height above the plane " + over}};
}

ExtremeResult run_resting(const Settings& s) {
  ExtremeResult res;
  res.data["resting"] = {{"max_speed", 0.0}, {"max_drift", 0.0}};
  ValueRange sink, height;
  for (IntegratorKind k : {IntegratorKind::Euler, IntegratorKind::Symplectic, IntegratorKind::Midpoint, IntegratorKind::RK4})
    rest_row(s.resting, k, 0.0, sink, height, res);
  rest_row(s.resting, IntegratorKind::Symplectic, s.resting.offset, sink, height, res);
  res.from_range(extremes_check("rest_max_sink"), sink, sink.hi());
  res.from_range(extremes_check("rest_max_jitter"), height, height.hi());
  return res;
}

}  // namespace tecido::suites::stability
