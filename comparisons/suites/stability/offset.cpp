#include "comparisons/suites/stability/offset.h"

#include "comparisons/suites/stability/theory.h"
#include "core/simulation/simulation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tecido::suites::stability {

namespace {

const std::string kCheck = extremes_check("offset_error_ulps_per_step");

/// Max over the run of the largest coordinate difference between `shifted` (less `off`) and `ref`,
/// both stepped n times; `unstable_step` is the first step either failed (0: none).
struct Paired {
  double err = 0.0;
  double sink = 0.0;  ///< deepest the shifted particle went below plane 0 (when there is one)
  long long unstable_step = 0;
};

Paired run_paired(Simulation& ref, Simulation& shifted, const Vec3& off, long long n, int particle) {
  Paired p;
  for (long long i = 0; i < n; ++i) {
    if (!ref.step() || !shifted.step()) {
      p.unstable_step = i + 1;
      return p;
    }
    const Vec3& x = shifted.particles().x[particle];
    p.err = std::max(p.err, ((x - off) - ref.particles().x[particle]).cwiseAbs().maxCoeff());
    if (!shifted.scene().planes.empty()) p.sink = std::max(p.sink, -shifted.scene().planes[0].side(x));
  }
  return p;
}

Scene spring_scene(const OffsetSettings& o, const OffsetSettings::Spring& sp, const Vec3& shift) {
  Scene s;
  s.dt = o.dt;
  s.particles.add(shift, Vec3::Zero(), 0.0, 1.0, true);
  s.particles.add(shift + Vec3(sp.rest_length + sp.amplitude, 0, 0), Vec3::Zero(), o.mass, 1.0, false);
  s.forces.springs.push_back(Spring{0, 1, o.stiffness, sp.rest_length, 0.0});
  return s;
}

/// A particle dropped from 1 m onto a 2 m x 2 m plane (k = 0.5, friction 0.5) under gravity.
Scene drop_scene(const OffsetSettings& o, const Vec3& shift) {
  Scene s;
  s.dt = o.dt;
  s.forces.gravity = Vec3(0, 0, -9.81);
  s.particles.add(shift + Vec3(0.1, 0.2, 1.0), Vec3(0.2, 0.1, 0.0), 1.0, 0.5, false);
  s.planes.push_back(make_bounded_plane(shift, Vec3::UnitZ(), Vec3::UnitX(), Vec2(1.0, 1.0), 0.5));
  return s;
}

void spring_row(const OffsetSettings& o, const OffsetSettings::Spring& sp, double O, ValueRange& worst,
                ExtremeResult& res) {
  const Vec3 off(O, O, O);
  const double u = ulp_of(O);
  Simulation ref(spring_scene(o, sp, Vec3::Zero())), sh(spring_scene(o, sp, off));
  const long long n = std::llround(o.periods * 2.0 * kPi / (std::sqrt(o.stiffness / o.mass) * o.dt));
  const Paired p = run_paired(ref, sh, off, n, 1);
  const std::string label = fmt::format("spring l = {:g} m, amplitude {:g} m, at {:g} m", sp.rest_length, sp.amplitude, O);
  if (p.unstable_step) {
    worst.missing(fmt::format("unstable at step {} ({})", p.unstable_step, label));
    res.rows.push_back({"offset", label, fmt::format("unstable at step {}", p.unstable_step), "broke: non-finite", {}});
    return;
  }
  const double per_step = p.err / (u * static_cast<double>(n)), rel = p.err / sp.amplitude;
  worst.add(per_step, label);
  res.data["offset"].push_back({{"kind", "spring"}, {"offset", O}, {"rest_length", sp.rest_length},
                                {"amplitude", sp.amplitude}, {"error", p.err}, {"relative", rel}, {"ulps_per_step", per_step}});
  res.rows.push_back(
      {"offset", label,
       fmt::format("max error {} m = {:.3g} ulp({:g}) over {} steps ({:.2g} ulp/step); {:.2g} of the amplitude", sci(p.err),
                   p.err / u, O, n, per_step, rel),
       "",
       ExtremeRow::Judge{"offset_degraded", {rel}, "ok: only storage rounding",
                         fmt::format("degraded: positions are stored to ulp = {:.2g} m, {:.1g} of the amplitude, each step",
                                     u, u / sp.amplitude)}});
}

void drop_row(const OffsetSettings& o, double O, ValueRange& worst, ExtremeResult& res) {
  const Vec3 off(O, O, O);
  const double u = ulp_of(O);
  Simulation ref(drop_scene(o, Vec3::Zero())), sh(drop_scene(o, off));
  const Paired p = run_paired(ref, sh, off, o.drop_steps, 0);
  const std::string label = fmt::format("particle dropped 1 m on a plane (k = 0.5, friction 0.5), at {:g} m", O);
  if (p.unstable_step) {
    worst.missing(fmt::format("unstable at step {} ({})", p.unstable_step, label));
    res.rows.push_back({"offset", label, fmt::format("unstable at step {}", p.unstable_step), "broke: non-finite", {}});
    return;
  }
  const double per_step = p.err / (u * static_cast<double>(o.drop_steps));
  worst.add(per_step, label);
  res.data["offset"].push_back({{"kind", "drop"}, {"offset", O}, {"error", p.err}, {"ulps_per_step", per_step}});
  const long long c_sh = sh.contacts().events, c_ref = ref.contacts().events;
  const std::string same = c_sh == c_ref ? "same contacts" : fmt::format("{} contacts against {}", c_sh, c_ref);
  res.rows.push_back(
      {"offset", label,
       fmt::format("max error {} m = {:.3g} ulp({:g}) over {} steps ({:.2g} ulp/step); max sink below the plane {} m; "
                   "{} contacts vs {} unshifted",
                   sci(p.err), p.err / u, O, o.drop_steps, per_step, sci(p.sink), c_sh, c_ref),
       p.sink > 0.0 ? "broke: ended below the plane"
                    : fmt::format("ok: {:.2g} of the 1 m drop, {}, never below the plane", p.err, same),
       {}});
}

}  // namespace

std::vector<CheckSpec> offset_checks(const Settings&) {
  return {{kCheck, [](const Tolerances& t) { return t.at_most("/stability/offset_error_ulps_per_step"); },
           "max |error vs unshifted| / (steps x ulp(offset)), worst case"}};
}

ExtremeResult run_offset(const Settings& s) {
  ExtremeResult res;
  res.data["offset"] = io::Json::array();
  ValueRange worst;
  for (double O : s.offset.offsets) {
    for (const OffsetSettings::Spring& sp : s.offset.springs) spring_row(s.offset, sp, O, worst, res);
    drop_row(s.offset, O, worst, res);
  }
  res.from_range(kCheck, worst, worst.hi());
  return res;
}

}  // namespace tecido::suites::stability
