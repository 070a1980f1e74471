#include "comparisons/suites/drift/drift_report.h"

#include "comparisons/io/atomic_file.h"
#include "comparisons/io/gnuplot.h"
#include "comparisons/suites/drift/theory.h"
#include "comparisons/suites/sweep.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tecido::suites::drift {

namespace {

/// The smallest and largest finite value of f over the rows with integrator `kind` (NaN, NaN when none).
template <class F>
std::pair<double, double> range_of(const std::vector<InvariantRow>& rows, IntegratorKind kind, F f) {
  double lo = INFINITY, hi = -INFINITY;
  for (const InvariantRow& r : rows) {
    if (r.kind != kind || !r.error.empty() || r.run.unstable_at_step) continue;
    const double v = f(r.run);
    if (!std::isfinite(v)) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (lo > hi) return {NAN, NAN};
  return {lo, hi};
}

std::string span(std::pair<double, double> r, const char* format) {
  if (std::isnan(r.first)) return "not measured";
  const std::string lo = fmt::format(fmt::runtime(format), r.first), hi = fmt::format(fmt::runtime(format), r.second);
  return lo == hi ? lo : lo + " to " + hi;
}

std::string seconds_or_never(double t, double of) {
  return std::isnan(t) ? fmt::format("never (of {:g} s simulated)", of) : fmt::format("{:.3g} s", t);
}

}  // namespace

std::string not_modelled_text(const io::Json& list) {
  if (list.empty()) return "nothing (exact twin)";
  std::string out;
  for (const auto& s : list) out += (out.empty() ? "" : "; ") + s.get<std::string>();
  return out;
}

std::string settings_markdown(const Settings& s) {
  return fmt::format(
      "Settings (comparisons/suites/drift/settings.h): {} steps per invariants run, sampled every {}; twin cloth {}x{} "
      "nodes, {} m apart, {} kg, ks = {} N/m, dt = {:.6g} s, {} s; falling from {} m for {} s; classic curtain "
      "{}x{} over {} m, {} kg, ks = {} N/m, dt = {} s, {} sweeps, kDP = {} while settling, rest below {} m/s, "
      "calibrator stops at a relative sag error of {}, validated at {} times the load.\n\n",
      s.steps, s.sample_every, s.twin_nodes, s.twin_nodes, s.twin_spacing, s.twin_mass, s.twin_stiffness, s.twin_dt,
      s.twin_seconds, s.fall_height, s.fall_seconds, s.classic_nodes, s.classic_nodes, s.classic_side, s.classic_mass,
      s.classic_stiffness, s.classic_dt, s.classic_piterations, s.classic_kdp, s.classic_rest_speed,
      s.classic_calibration_tolerance, s.classic_load_factor);
}

std::string invariants_method(const Settings& s) {
  return fmt::format(
      "### (a) Invariants over {} steps\n\nRelative energy error |E(t) - E0| / E0 sampled every {} steps; growth "
      "rate = least-squares slope of the relative error against time; last/first half = the largest error of the "
      "run's second half over that of its first half (about 1 when the error oscillates without trend, > 1 when it "
      "grows). Momentum error = max over samples of |P(t) - P0| / max(sum m|v0|, sum m|v(t)|). Angular momentum "
      "error = max over samples of |L(t) - L0| / max(sum m|x0||v0|, sum m|x(t)||v(t)|), L = sum m x × v; "
      "\"vs theory\" subtracts from L(t) - L0 the change theory predicts, summed step by step (none for symplectic "
      "Euler, which conserves L; Cooper's Runge-Kutta formula for the others, see below).\n\n",
      s.steps, s.sample_every);
}

std::string invariants_table(const std::vector<InvariantRow>& rows) {
  std::string md =
      "| scene | integrator | final rel. energy error | max rel. error | growth rate [1/s] | last/first half | momentum "
      "error | angular momentum error | angular momentum vs theory |\n|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const InvariantRow& r : rows) {
    const char* name = integrator_name(r.kind);
    if (!r.error.empty()) {
      md += fmt::format("| {} | {} | failed: {} | | | | | | |\n", r.scene, name, r.error);
    } else if (r.run.unstable_at_step) {
      md += fmt::format("| {} | {} | unstable at step {} | | | | | | |\n", r.scene, name, r.run.unstable_at_step);
    } else {
      const InvariantRun& x = r.run;
      md += fmt::format("| {} | {} | {:.3e} | {:.3e} | {:.3e} | {:.2f} | {:.1e} | {:.1e} | {:.1e} |\n", r.scene, name,
                        x.final_rel_energy, x.max_rel_energy, x.growth_rate, x.last_over_first_half, x.momentum_error,
                        x.angular_momentum_error, x.angular_momentum_vs_theory);
    }
  }
  return md + "\n";
}

std::string energy_plot(const SuiteContext& ctx, const std::string& scene, const std::vector<InvariantRow>& rows,
                        std::vector<std::string>& plots) {
  std::string dat, plot = "plot ";
  int block = 0;
  for (const InvariantRow& r : rows) {
    if (r.scene != scene || !r.error.empty()) continue;
    dat += fmt::format("# {}\n", integrator_name(r.kind));
    for (const auto& p : r.run.energy_curve) dat += fmt::format("{:.9g} {:.9g}\n", p[0], std::max(p[1], 1e-17));
    dat += "\n\n";
    plot += fmt::format("{}'{}.dat' index {} using 1:2 with lines title '{}'", block ? ", " : "", scene, block,
                        integrator_name(r.kind));
    ++block;
  }
  const std::string dir = ctx.out_dir + "/drift";
  io::write_file_atomic(dir + "/" + scene + ".dat", dat);
  if (!ctx.gnuplot || block == 0) return "";
  const std::string script = fmt::format(
      "set terminal svg size 700,380 dynamic font 'sans,11'\nset output '{0}-energy.svg'\nset title '{0}: relative "
      "energy error'\nset logscale y\nset format y '10^{{%L}}'\nset grid\nset key outside right\nset xlabel 'time [s]'\n"
      "set ylabel '|E - E0| / E0'\n{1}\n",
      scene, plot);
  if (!io::run_gnuplot(dir, scene + "-energy", script)) return "";
  plots.push_back("drift/" + scene + "-energy.svg");
  return fmt::format("![{0} energy error](drift/{0}-energy.svg)\n\n", scene);
}

std::string invariants_findings(const std::vector<InvariantRow>& rows) {
  using K = IntegratorKind;
  auto halves = [](const InvariantRun& r) { return r.last_over_first_half; };
  auto l_err = [](const InvariantRun& r) { return r.angular_momentum_error; };
  auto l_theory = [](const InvariantRun& r) { return r.angular_momentum_vs_theory; };
  double p_max = 0.0;
  for (const InvariantRow& r : rows)
    if (r.error.empty() && !r.run.unstable_at_step) p_max = std::max(p_max, r.run.momentum_error);
  std::string md =
      "What theory says: symplectic Euler preserves a modified energy, so its error oscillates without trend; explicit "
      "Euler multiplies each mode's energy by about (1 + (omega h)^2) a step and grows; midpoint grows much more "
      "slowly (order (omega h)^4 per step for an oscillator) and RK4 slowly loses energy. Every method conserves "
      "linear momentum to round-off, because each force evaluation sums to zero and the updates are linear in it. "
      "Symplectic Euler also conserves angular momentum exactly under central spring forces "
      "(L_{n+1} = sum m x_n × v_{n+1} = L_n + h sum x_n × f(x_n) = L_n); an explicit Runge-Kutta method changes it "
      "per step by h^2 sum_ij (b_i b_j - b_i a_ij - b_j a_ji) sum V_i × F_j over its stage velocities and forces "
      "(Cooper 1987; for explicit Euler h^2 sum v × f), which the suite sums and subtracts.\n\n";
  md += fmt::format(
      "This run's table: symplectic Euler's last/first-half ratio is {} (its max relative energy error {}); explicit "
      "Euler's is {}; every momentum error is at most {:.1e}. Angular momentum: symplectic Euler's error is {}; the "
      "others change it by {} (explicit Euler), {} (midpoint), {} (RK4) of its scale, and the change matches Cooper's "
      "prediction to within {} (explicit Euler), {} (midpoint), {} (RK4).\n\n",
      span(range_of(rows, K::Symplectic, halves), "{:.2f}"),
      span(range_of(rows, K::Symplectic, [](const InvariantRun& r) { return r.max_rel_energy; }), "{:.2e}"),
      span(range_of(rows, K::Euler, halves), "{:.2f}"), p_max, span(range_of(rows, K::Symplectic, l_err), "{:.1e}"),
      span(range_of(rows, K::Euler, l_err), "{:.1e}"), span(range_of(rows, K::Midpoint, l_err), "{:.1e}"),
      span(range_of(rows, K::RK4, l_err), "{:.1e}"), span(range_of(rows, K::Euler, l_theory), "{:.1e}"),
      span(range_of(rows, K::Midpoint, l_theory), "{:.1e}"), span(range_of(rows, K::RK4, l_theory), "{:.1e}"));
  return md;
}

std::string twin_markdown(const SuiteContext& ctx, const Settings& s, const io::Json& result,
                          std::vector<std::string>& plots) {
  std::string md = fmt::format(
      "**Deformable twin** (btDeformableMultiBodyDynamicsWorld, explicit, double): an undamped {0}x{0} cloth ({1:g} m, "
      "{2:g} kg, ks = {3:g} N/m, two corner pins, dt = {4:.6g} s) against core's symplectic Euler. ",
      s.twin_nodes, s.twin_spacing * (s.twin_nodes - 1), s.twin_mass, s.twin_stiffness, s.twin_dt);
  if (const std::string* err = case_error(result)) return md + "Not measured: " + *err + ".\n\n";
  std::string dat;
  for (const auto& row : result.at("curve"))
    dat += fmt::format("{:.6f} {:.6e} {:.6e}\n", get_num(row[0]), std::max(get_num(row[1]), 1e-17), std::max(get_num(row[2]), 1e-17));
  io::write_file_atomic(ctx.out_dir + "/drift/twin.dat", dat);
  const auto& c = result.at("crossings");
  md += fmt::format("Largest RMS node distance over the first {:g} s: **{:.2e} m**. RMS first above {:g} m at {}, above "
                    "{:g} m at {}, above {:g} m at {}: rounding differences, amplified by the cloth's chaotic motion. ",
                    s.twin_window, get_num(result.at("rms_window")), s.twin_thresholds[0],
                    seconds_or_never(get_num(c[0]), s.twin_seconds), s.twin_thresholds[1],
                    seconds_or_never(get_num(c[1]), s.twin_seconds), s.twin_thresholds[2],
                    seconds_or_never(get_num(c[2]), s.twin_seconds));
  if (!result.at("unstable").is_null())
    md += fmt::format("The run went unstable at step {} ({}). ", result["unstable"]["step"].get<long long>(),
                      result["unstable"]["engine"].get<std::string>());
  md += "Not modelled: " + not_modelled_text(result.at("not_modelled")) + ".\n\n";
  const std::string script =
      "set terminal svg size 700,360 dynamic font 'sans,11'\nset output 'twin.svg'\nset title 'core symplectic vs Bullet "
      "deformable twin'\nset logscale y\nset format y '10^{%L}'\nset grid\nset xlabel 'time [s]'\nset ylabel 'node "
      "distance [m]'\nplot 'twin.dat' using 1:2 with lines title 'RMS', 'twin.dat' using 1:3 with lines title 'max'\n";
  if (ctx.gnuplot && io::run_gnuplot(ctx.out_dir + "/drift", "twin", script)) {
    plots.push_back("drift/twin.svg");
    md += "![twin drift](drift/twin.svg)\n\n";
  }
  return md;
}

std::string falling_markdown(const Settings& s, const io::Json& result) {
  std::string md = fmt::format("**Falling onto a plane**: the same cloth released flat {:g} m above a floor (k = 0). ",
                               s.fall_height);
  if (const std::string* err = case_error(result)) return md + "Not measured: " + *err + ".\n\n";
  auto t = [&](const char* key) {
    const double v = get_num(result.at(key));
    return std::isnan(v) ? std::string("no contact") : fmt::format("{:.5f} s", v);
  };
  md += fmt::format(
      "First ground contact: analytic {}; core (bisected, symplectic Euler) {}; Bullet twin {} (first step end with a "
      "node within its collision margin, {:.3g} m: analytic {}; step {:.4f} s). Height after {:g} s: core max |z| = "
      "{:.2e} m (resting contact), Bullet max z = {:.2e} m (held at the margin).",
      t("t_exact"), t("t_core"), t("t_twin"), get_num(result.at("margin")), t("t_exact_margin"), s.twin_dt,
      s.fall_seconds, get_num(result.at("z_core")), get_num(result.at("z_twin")));
  if (!result.at("unstable").is_null())
    md += fmt::format(" The run went unstable at step {} ({}).", result["unstable"]["step"].get<long long>(),
                      result["unstable"]["engine"].get<std::string>());
  return md + "\n\n";
}

std::string classic_markdown(const Settings& s, const io::Json& result) {
  std::string md = fmt::format(
      "**Classic soft body** (btSoftBody, position-based links): kLST calibrated by matching the settled mean sag of a "
      "{0}x{0} curtain hung from its top row ({1:g} m, {2:g} kg, ks = {3:g} N/m, dt = {4:g} s, {5} sweeps, kDP = {6:g}), "
      "then checked at {7:g} times the load, which the calibration never saw. ",
      s.classic_nodes, s.classic_side, s.classic_mass, s.classic_stiffness, s.classic_dt, s.classic_piterations,
      s.classic_kdp, s.classic_load_factor);
  if (const std::string* err = case_error(result)) return md + "Not measured: " + *err + ".\n\n";
  const io::Json &c = result.at("calibration"), &l = result.at("load");
  md += fmt::format(
      "Calibration: **kLST = {:.4g}** (sag core {:.4g} mm, Bullet {:.4g} mm after {} settles: a relative sag error of "
      "{:.2e}, where the calibrator stops at {:g}; that is its own stopping rule, which says the search converged, not "
      "that the engines agree; Bullet's default kLST = 1 sags {:.3g} mm; settled shapes {:.3g} mm RMS apart). ",
      get_num(c.at("klst")), 1e3 * get_num(c.at("core_sag")), 1e3 * get_num(c.at("bullet_sag")),
      c.at("evaluations").get<int>(), get_num(c.at("relative_error")), s.classic_calibration_tolerance,
      1e3 * get_num(c.at("sag_at_klst_1")), 1e3 * get_num(c.at("shape_rms")));
  const double ratio = get_num(l.at("sag_ratio")), expected = classic_sag_ratio(s.classic_load_factor);
  const bool follows = std::abs(ratio - 1.0) < std::abs(ratio - expected);
  md += fmt::format(
      "At {:g} times the load: sag core {:.4g} mm, Bullet {:.4g} mm, Bullet/core = {:.3f} (1 if the classic body "
      "followed a Hooke cloth; {:.3f} if its links do not feel the load); Bullet's settled shape moved by at most "
      "{:.2g} m from the calibration load's (0: bit-identical), and core's and Bullet's settled shapes are {:.3g} mm RMS apart. ",
      get_num(l.at("factor")), 1e3 * get_num(l.at("core_sag")), 1e3 * get_num(l.at("bullet_sag")), ratio, expected,
      get_num(l.at("bullet_shape_change")), 1e3 * get_num(l.at("shape_rms")));
  md += follows ? "**Finding**: the ratio is nearer 1 than the load-independent value: at this load the classic body "
                  "follows the Hooke cloth it was calibrated against.\n\n"
                : "**Finding**: the ratio is nearer the load-independent value than 1: the position-based cloth does not "
                  "follow a Hooke cloth to another load (each sweep moves the nodes by a fraction kLST of the violation, "
                  "split by ratios of their inverse masses, so the masses drop out), and a kLST calibrated at one load "
                  "is wrong at any other, as it is for another dt, number of sweeps or mesh.\n\n";
  return md + "Not modelled: " + not_modelled_text(result.at("not_modelled")) + ".\n\n";
}

std::string wind_markdown(const io::Json& result) {
  std::string md = "**Cloth in wind** (a force per particle, and linear drag): not compared, because neither Bullet "
                   "engine models them as core does. ";
  if (const std::string* err = case_error(result)) return md + "Not listed: " + *err + ".\n";
  return md + "Deformable twin: " + not_modelled_text(result.at("twin")) + ". Classic: " +
         not_modelled_text(result.at("classic")) + ".\n";
}

}  // namespace tecido::suites::drift
