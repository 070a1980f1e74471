#include "comparisons/suites/stability/extremes_notes.h"

#include "comparisons/suites/stability/theory.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tecido::suites::stability {

namespace {

std::string no_result(const char* title) {
  return fmt::format("**{}.** No result: the group failed (its checks say why).\n\n", title);
}

/// "79" when lo and hi print alike at 4 digits, else "79 to 81".
std::string span(double lo, double hi) {
  const std::string a = fmt::format("{:.4g}", lo), b = fmt::format("{:.4g}", hi);
  return a == b ? a : a + " to " + b;
}

double number(const io::Json& j, const char* key) {
  const io::Json& v = j.at(key);
  return v.is_number() ? v.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

std::string offset_note(const Settings&, const io::Json& data, const VerdictBands& bands) {
  if (!data.contains("offset") || data["offset"].empty()) return no_result("Offsets");
  const io::Json& runs = data["offset"];
  double top = 0.0, worst = 0.0;
  for (const io::Json& r : runs) {
    top = std::max(top, number(r, "offset"));
    worst = std::max(worst, number(r, "ulps_per_step"));
  }
  std::string at_top;
  for (const io::Json& r : runs)
    if (number(r, "offset") == top && r.at("kind") == "spring")
      at_top += fmt::format("{}{:.2g} of the amplitude for the {:g} m spring moving {:g} m", at_top.empty() ? "" : ", ",
                            number(r, "relative"), number(r, "rest_length"), number(r, "amplitude"));
  return fmt::format(
      "**Offsets.** A spring's x_j - x_i is exact when both ends are near the same large offset (Sterbenz), and so is "
      "a plane's side test p - position; what is lost is the storage of positions: at {0:g} m a double holds "
      "positions to ulp = {1:.2g} m, and each step's x += h v rounds to it. The error against the unshifted run is "
      "therefore a sum of per-step roundings, bounded by about one ulp of the offset per step (checked; the worst run "
      "here: {2:.2g} ulp per step), and it matters in proportion to ulp/amplitude: at {0:g} m the error reached {3}. "
      "The table calls a run degraded when its error exceeds {4:g} of its amplitude.\n\n",
      top, ulp_of(top), worst, at_top, bands.at("offset_degraded").hi);
}

std::string mass_ratio_note(const Settings& s, const io::Json& data) {
  if (!data.contains("mass_ratio")) return no_result("Mass ratios");
  const MassRatioSettings& mr = s.mass_ratio;
  int systems = 0, stable = 0;
  double lo = INFINITY, hi = -INFINITY;
  for (auto it = data["mass_ratio"].begin(); it != data["mass_ratio"].end(); ++it) {
    ++systems;
    bool all = true;
    for (const io::Json& run : it.value()) {
      all = all && run.at("found").get<bool>();
      if (run.at("reference").get<bool>() || !run.contains("smaller_than_equal")) continue;
      const double x = number(run, "smaller_than_equal");
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    stable += all ? 1 : 0;
  }
  const double theory = pair_omega_max(mr.stiffness, mr.heavy, mr.light) / pair_omega_max(mr.stiffness, mr.heavy, mr.heavy);
  return fmt::format(
      "**Mass ratios.** {} of the {} systems (mass ratios 1 and {:g}) had a stable step with every integrator. The largest "
      "stable step is that of the fastest mode, omega_max^2 = ks (1/m1 + 1/m2) for a free pair: the light particle "
      "sets it, {:.4g}x smaller than the equal-mass pair's by theory, {}x measured. A cloth with one "
      "very light node pays that price for the whole cloth.\n\n",
      stable, systems, mr.heavy / mr.light, theory, span(lo, hi));
}

std::string near_zero_note(const Settings& s, const io::Json& data) {
  if (!data.contains("near_zero")) return no_result("Near-zero rest lengths");
  const io::Json& d = data["near_zero"];
  const long long bad = d.at("nonfinite").get<long long>(), runs = d.at("runs").get<long long>();
  double lo = INFINITY, hi = -INFINITY;
  for (const io::Json& x : d.at("deviation_over_l")) {
    lo = std::min(lo, x.get<double>());
    hi = std::max(hi, x.get<double>());
  }
  const std::vector<double>& ls = s.near_zero.rest_lengths;
  return fmt::format(
      "**Near-zero rest lengths.** {}: the force is ks (|d| - l) d/|d| and the engine skips a spring whose |d| is 0, "
      "the one place the direction is undefined. The cost of that rule is visible: a spring of rest length l > 0 "
      "whose ends coincide exerts nothing, and the ends stay l short of rest (up to {:g} m here). Passing the anchor, "
      "the runs deviate from the l = 0 run by {} times l. |d| is computed as sqrt(|d|^2), which underflows "
      "to 0 below about {:.3g} m, where the same rule applies.\n\n",
      bad == 0 ? fmt::format("No NaN or infinity in any of the {} runs and forces", runs)
               : fmt::format("{} of the {} runs and forces were not finite", bad, runs),
      ls.empty() ? 0.0 : *std::max_element(ls.begin(), ls.end()), span(lo, hi), underflow_separation());
}

std::string resting_note(const Settings& s, const io::Json& data) {
  if (!data.contains("resting")) return no_result("Resting contact");
  const double v = number(data["resting"], "max_speed"), drift = number(data["resting"], "max_drift");
  return fmt::format(
      "**Resting contact.** The first step's free fall crosses the plane from on it, the bisection finds the contact "
      "at once, |vn| is below the static threshold and the contact becomes resting: the plane then cancels the "
      "normal acceleration. {}\n\n",
      v == 0.0 && drift == 0.0
          ? fmt::format("Over the {} steps of every finite run the particle stayed still, bit for bit: its largest "
                        "speed and drift were both exactly 0.",
                        s.resting.steps)
          : fmt::format("Over the finite runs its largest speed was {:.3g} m/s and its largest drift {:.3g} m.", v, drift));
}

std::string tunnelling_note(const Settings& s, const io::Json& data) {
  if (!data.contains("tunnelling")) return no_result("Tunnelling");
  const io::Json& d = data["tunnelling"];
  const long long wrong = d.at("wrong_side_steps").get<long long>(), runs = d.at("runs").get<long long>();
  const double max_dt = number(d, "max_dt");
  const std::vector<double>& v = s.tunnelling.speeds;
  const double vmax = v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
  const std::string how = "**Tunnelling.** The plane test works on the step's whole segment p1 -> p2 and each particle "
                          "remembers its side";
  if (wrong != 0)
    return fmt::format("{}; yet {} steps ended below the plane in {} runs.\n\n", how, wrong, runs);
  return fmt::format("{}, so step length does not matter: in all {} runs, with steps up to {:g} s (at {:g} m/s one step "
                     "spans {:g} m), no step ended below the plane.\n\n",
                     how, runs, max_dt, vmax, vmax * max_dt);
}

std::string extremes_notes(const Settings& s, const io::Json& data, const VerdictBands& bands) {
  return offset_note(s, data, bands) + mass_ratio_note(s, data) + near_zero_note(s, data) + resting_note(s, data) +
         tunnelling_note(s, data);
}

}  // namespace tecido::suites::stability
