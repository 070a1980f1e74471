#include "comparisons/suites/stability/mass_ratio.h"

#include "comparisons/suites/stability/oscillator.h"
#include "comparisons/suites/stability/theory.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tecido::suites::stability {

namespace {

struct System {
  std::string label;
  Scene scene;
  double omega_max = 0.0;
};

/// Free pair m1 - m2, or the chain anchor - m1 - m2; zero rest lengths, released 1 m stretched.
System make_system(double ks, double m1, double m2, bool anchored) {
  System sys;
  Scene& s = sys.scene;
  if (anchored) {
    s.particles.add(Vec3::Zero(), Vec3::Zero(), 0.0, 1.0, true);
    s.particles.add(Vec3::Zero(), Vec3::Zero(), m1, 1.0, false);
    s.particles.add(Vec3(1.0, 0, 0), Vec3::Zero(), m2, 1.0, false);
    s.forces.springs.push_back(Spring{0, 1, ks, 0.0, 0.0});
    s.forces.springs.push_back(Spring{1, 2, ks, 0.0, 0.0});
    sys.omega_max = chain_omega_max(ks, m1, m2);
    sys.label = fmt::format("chain anchor - {:g} kg - {:g} kg", m1, m2);
  } else {
    s.particles.add(Vec3::Zero(), Vec3::Zero(), m1, 1.0, false);
    s.particles.add(Vec3(1.0, 0, 0), Vec3::Zero(), m2, 1.0, false);
    s.forces.springs.push_back(Spring{0, 1, ks, 0.0, 0.0});
    sys.omega_max = pair_omega_max(ks, m1, m2);
    sys.label = fmt::format("free pair {:g} kg : {:g} kg", m1, m2);
  }
  return sys;
}

/// Largest stable step of `sys` with integrator k; the amplitude is the largest spring extension
/// (relative coordinates: the free pair's centre of mass is at rest).
StableStep max_step(const Settings& s, const System& sys, IntegratorKind k) {
  auto amp = [&sys](const Particles& p) {
    double a = 0.0;
    for (const Spring& sp : sys.scene.forces.springs) a = std::max(a, (p.x[sp.j] - p.x[sp.i]).norm());
    return a;
  };
  return find_max_stable_step(
      [&](double h) {
        Scene t = sys.scene;
        t.integrator = k;
        t.dt = h;
        const BoundedRun r = run_bounded(t, steps_for(s.periods, sys.omega_max, h), amp, s.amplitude_bound);
        return r.finite && r.bounded;
      },
      1.0 / sys.omega_max, s.rel_tol, s.max_doublings, s.max_halvings);
}

/// One system's row: each bounded integrator's h_max against its limit; `h_ref` holds the first
/// system's steps (the equal-mass reference) and is filled when `reference`.
void system_row(const Settings& s, const System& sys, bool reference, std::vector<double>& h_ref, ValueRange& ratios,
                ExtremeResult& res) {
  std::string measured;
  std::vector<double> row_ratios;
  for (std::size_t i = 0; i < s.bounded.size(); ++i) {
    const IntegratorKind k = s.bounded[i];
    const StableStep st = max_step(s, sys, k);
    const std::string where = fmt::format("{}, {}", sys.label, integrator_name(k));
    io::Json& d = res.data["mass_ratio"][sys.label][integrator_name(k)];
    d = {{"found", st.found}, {"omega_max", sys.omega_max}, {"reference", reference}};
    if (!st.found) {
      ratios.missing(fmt::format("no stable step ({}; unstable down to h = {:.3g} s)", where, st.h_unstable));
      measured += fmt::format("{}{}: no stable step", i ? "; " : "", integrator_name(k));
      row_ratios.push_back(std::nan(""));
      continue;
    }
    const double limit = stable_limit(k), ratio = st.h * sys.omega_max / limit;
    ratios.add(ratio, where);
    row_ratios.push_back(ratio);
    if (reference) h_ref[i] = st.h;
    measured += fmt::format("{}{}: h_max = {} s, h_max omega_max = {:.5f} (/{:.3f} = {:.4f}){}", i ? "; " : "",
                            integrator_name(k), sci(st.h), st.h * sys.omega_max, limit, ratio,
                            reference ? "" : fmt::format(", {:.4g}x smaller than the equal-mass pair", h_ref[i] / st.h));
    d["h_max"] = st.h;
    d["ratio"] = ratio;
    d["smaller_than_equal"] = h_ref[i] / st.h;
  }
  res.rows.push_back({"mass ratio", sys.label + fmt::format(" (ks = {:g} N/m, omega_max = {:.6g} 1/s)",
                                                            s.mass_ratio.stiffness, sys.omega_max),
                      measured, "",
                      ExtremeRow::Judge{"ratio", row_ratios,
                                        reference ? "ok: reference" : "ok: stable, but the step is set by the light particle",
                                        "broke: limit differs from linear theory"}});
}

}  // namespace

std::vector<CheckSpec> mass_ratio_checks(const Settings& s) {
  const std::string note = fmt::format("h_max omega_max / theory across mass ratios 1 and {:g}",
                                       s.mass_ratio.heavy / s.mass_ratio.light);
  auto band = [](const Tolerances& t) { return t.between("/stability/ratio_lo", "/stability/ratio_hi"); };
  return {{extremes_check("mass_ratio_min"), band, note}, {extremes_check("mass_ratio_max"), band, note}};
}

ExtremeResult run_mass_ratio(const Settings& s) {
  const MassRatioSettings& mr = s.mass_ratio;
  const System systems[] = {make_system(mr.stiffness, mr.heavy, mr.heavy, false),
                            make_system(mr.stiffness, mr.heavy, mr.light, false),
                            make_system(mr.stiffness, mr.heavy, mr.light, true)};
  ExtremeResult res;
  ValueRange ratios;
  std::vector<double> h_ref(s.bounded.size(), std::nan(""));
  for (std::size_t i = 0; i < std::size(systems); ++i) system_row(s, systems[i], i == 0, h_ref, ratios, res);
  res.from_range(extremes_check("mass_ratio_min"), ratios, ratios.lo());
  res.from_range(extremes_check("mass_ratio_max"), ratios, ratios.hi());
  return res;
}

}  // namespace tecido::suites::stability
