#include "comparisons/suites/stability/near_zero.h"

#include "comparisons/suites/stability/theory.h"
#include "core/dynamics/force_model.h"
#include "core/simulation/simulation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace tecido::suites::stability {

namespace {

const char* kGroup = "near-zero rest length";

/// Counts of the group's runs and forces, and how many were not finite.
struct Tally {
  long long runs = 0, nonfinite = 0;
  void add(bool finite) {
    ++runs;
    nonfinite += finite ? 0 : 1;
  }
};

/// Symplectic, ks = 1 N/m, m = 1 kg, released `amplitude` from the anchor and `y0` beside it.
Scene through_scene(const NearZeroSettings& z, double l, double y0) {
  Scene s;
  s.dt = z.dt;
  s.particles.add(Vec3::Zero(), Vec3::Zero(), 0.0, 1.0, true);
  s.particles.add(Vec3(z.amplitude, y0, 0), Vec3::Zero(), 1.0, 1.0, false);
  s.forces.springs.push_back(Spring{0, 1, 1.0, l, 0.0});
  return s;
}

/// Each rest length oscillating through the anchor, compared with the l = 0 run step by step.
void through_rows(const NearZeroSettings& z, double y0, Tally& tally, ExtremeResult& res) {
  const long long n = std::llround(z.periods * 2.0 * kPi / z.dt);  // omega = 1
  Simulation zero(through_scene(z, 0.0, y0));
  std::vector<std::unique_ptr<Simulation>> sims;  // a Simulation is not movable (its callbacks hold this)
  for (double l : z.rest_lengths) sims.push_back(std::make_unique<Simulation>(through_scene(z, l, y0)));
  const std::size_t m = sims.size();
  std::vector<double> dev(m, 0.0), amax(m, 0.0);
  std::vector<bool> fin(m, true);
  for (long long i = 0; i < n; ++i) {
    zero.step();
    for (std::size_t k = 0; k < m; ++k) {
      if (!fin[k]) continue;
      fin[k] = sims[k]->step();
      dev[k] = std::max(dev[k], (sims[k]->particles().x[1] - zero.particles().x[1]).norm());
      amax[k] = std::max(amax[k], sims[k]->particles().x[1].norm());
    }
  }
  for (std::size_t k = 0; k < m; ++k) {
    const double l = z.rest_lengths[k];
    tally.add(fin[k]);
    if (fin[k]) res.data["near_zero"]["deviation_over_l"].push_back(dev[k] / l);
    res.rows.push_back(
        {kGroup,
         fmt::format("l = {:g} m, oscillating {:g} m through the anchor{}", l, z.amplitude,
                     y0 != 0.0 ? fmt::format(" ({:g} m beside it)", y0) : ""),
         fin[k] ? fmt::format("finite: yes; max |x| = {} m; max deviation from the l = 0 run {} m (l itself: {:g})",
                              sci(amax[k]), sci(dev[k]), l)
                : fmt::format("finite: NO, unstable at step {}", sims[k]->instability()->step),
         fin[k] ? fmt::format("ok: finite; deviation {:.3g} l (the period changes by O(l/amplitude), a phase drift)",
                              dev[k] / l)
                : "broke: non-finite",
         {}});
  }
}

/// Both ends at one point: the force is skipped (exactly 0) and the run stays finite.
void coincident_rows(const NearZeroSettings& z, Tally& tally, ValueRange& force, ExtremeResult& res) {
  std::vector<double> ls = z.rest_lengths;
  ls.push_back(0.0);
  for (double l : ls) {
    Scene s;
    s.dt = z.dt;
    s.particles.add(Vec3(0.5, 0.5, 0.5), Vec3::Zero(), 0.0, 1.0, true);
    s.particles.add(Vec3(0.5, 0.5, 0.5), Vec3::Zero(), 1.0, 1.0, false);
    s.forces.springs.push_back(Spring{0, 1, 1.0, l, 0.0});
    std::vector<Vec3> f;
    accumulate_spring_forces(s.forces.springs, s.particles.x, s.particles.v, f);
    const std::string label = fmt::format("l = {:g} m, both ends at the same point", l);
    force.add(f[1].norm(), label);
    Simulation sim(s);
    const bool ok = sim.run(z.coincident_steps);
    tally.add(ok && f[1].allFinite());
    const double moved = (sim.particles().x[1] - s.particles.x[1]).norm();
    res.rows.push_back(
        {kGroup, label,
         fmt::format("force {:g} N (exact 0: skipped); after {} steps finite: {}, moved {} m", f[1].norm(),
                     z.coincident_steps, ok ? "yes" : "NO", sci(moved)),
         !ok ? "broke: non-finite"
             : (l > 0.0 ? fmt::format("ok, documented limitation: should be pushed out to l, stays {:g} m short", l)
                        : "ok: at rest at its rest length"),
         {}});
  }
}

/// Ends closer than sqrt(DBL_MIN): |d|^2 subnormal, or rounded to 0.
void separation_rows(const NearZeroSettings& z, Tally& tally, ExtremeResult& res) {
  const double l = z.tiny_rest_length;
  for (double d : z.separations) {
    std::vector<Spring> sp{Spring{0, 1, 1.0, l, 0.0}};
    std::vector<Vec3> x{Vec3::Zero(), Vec3(d, 0, 0)}, v{Vec3::Zero(), Vec3::Zero()}, f;
    accumulate_spring_forces(sp, x, v, f);
    const bool fin = f[0].allFinite() && f[1].allFinite();
    tally.add(fin);
    res.rows.push_back(
        {kGroup,
         fmt::format("l = {:g} m, ends {:g} m apart (|d|^2 {})", l, d, d * d > 0.0 ? "subnormal" : "underflows to 0"),
         fmt::format("force on the free end {} N (expected +{:g} N, pushing apart); finite: {}", sci(f[1].x()), l - d,
                     fin ? "yes" : "NO"),
         !fin ? "broke: non-finite"
              : (f[1].x() > 0.0 ? fmt::format("ok: direction kept (|u| - 1 = {:.1e})", std::abs(f[1].x()) / (l - d) - 1.0)
                                : "ok, documented limitation: |d| = 0 in floating point, force skipped"),
         {}});
  }
}

}  // namespace

std::vector<CheckSpec> near_zero_checks(const Settings&) {
  return {{extremes_check("near_zero_nonfinite"), [](const Tolerances& t) { return t.at_most("/stability/near_zero_nonfinite"); },
           "runs or forces with NaN/Inf among near-zero rest lengths"},
          {extremes_check("zero_length_force"), [](const Tolerances& t) { return t.at_most("/stability/zero_length_force"); },
           "force of a spring whose ends coincide: skipped, exactly 0"}};
}

ExtremeResult run_near_zero(const Settings& s) {
  ExtremeResult res;
  res.data["near_zero"]["deviation_over_l"] = io::Json::array();
  Tally tally;
  ValueRange force;
  for (double y0 : {0.0, s.near_zero.beside}) through_rows(s.near_zero, y0, tally, res);
  coincident_rows(s.near_zero, tally, force, res);
  separation_rows(s.near_zero, tally, res);
  res.set(extremes_check("near_zero_nonfinite"), static_cast<double>(tally.nonfinite));
  res.from_range(extremes_check("zero_length_force"), force, force.hi());
  res.data["near_zero"]["nonfinite"] = tally.nonfinite;
  res.data["near_zero"]["runs"] = tally.runs;
  return res;
}

}  // namespace tecido::suites::stability
