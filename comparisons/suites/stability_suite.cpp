#include "comparisons/suites/stability_suite.h"

#include "comparisons/io/atomic_file.h"
#include "comparisons/io/gnuplot.h"
#include "comparisons/suites/sweep.h"
#include "core/dynamics/simulation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <exception>
#include <iterator>
#include <limits>
#include <memory>

namespace tecido::suites {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

StableStep find_max_stable_step(const std::function<bool(double)>& stable, double h_start, double rel_tol,
                                int max_doublings, int max_halvings) {
  StableStep r;
  auto test = [&](double h) {
    ++r.runs;
    return stable(h);
  };
  double lo = 0.0, hi = 0.0;
  if (test(h_start)) {
    lo = h_start;
    for (int k = 0; k < max_doublings; ++k) {
      const double h = 2.0 * lo;
      if (!test(h)) {
        hi = h;
        break;
      }
      lo = h;
    }
    if (hi == 0.0) {  // stable at every h tried: report the largest
      r.found = true;
      r.h = lo;
      return r;
    }
  } else {
    hi = h_start;
    for (int k = 0; k < max_halvings; ++k) {
      const double h = 0.5 * hi;
      if (test(h)) {
        lo = h;
        break;
      }
      hi = h;
    }
    if (lo == 0.0) {  // unstable at every h tried
      r.h_unstable = hi;
      return r;
    }
  }
  while (hi - lo > rel_tol * lo) {
    const double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) break;
    if (test(mid)) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  r.found = true;
  r.h = lo;
  r.h_unstable = hi;
  return r;
}

double amplification(IntegratorKind k, double c) {
  switch (k) {
    case IntegratorKind::Euler: return std::sqrt(1.0 + c * c);
    case IntegratorKind::Midpoint: return std::sqrt(1.0 + c * c * c * c / 4.0);
    case IntegratorKind::RK4: {
      const double re = 1.0 - c * c / 2.0 + c * c * c * c / 24.0, im = c - c * c * c / 6.0;
      return std::sqrt(re * re + im * im);
    }
    case IntegratorKind::Symplectic: {
      // Update matrix [[1 - c^2, c], [-c, 1]] on (x, v/omega): trace 2 - c^2, determinant 1.
      if (c <= 2.0) return 1.0;
      const double b = c * c - 2.0;
      return 0.5 * (b + std::sqrt(b * b - 4.0));
    }
  }
  return std::nan("");
}

namespace {

Scene oscillator_scene(IntegratorKind k, double ks, double m, double h) {
  Scene s;
  s.integrator = k;
  s.dt = h;
  s.particles.add(Vec3::Zero(), Vec3::Zero(), 0.0, 1.0, true);
  s.particles.add(Vec3(1.0, 0, 0), Vec3::Zero(), m, 1.0, false);
  s.forces.springs.push_back(Spring{0, 1, ks, 0.0, 0.0});
  return s;
}

/// Steps `scene` up to n times, stopping at the first non-finite step or when amp(particles)
/// exceeds limit.
struct BoundedRun {
  bool finite = true;
  bool bounded = true;
  long long steps = 0;
  double max_amp = 0.0;
};

BoundedRun run_bounded(const Scene& scene, long long n, const std::function<double(const Particles&)>& amp,
                       double limit) {
  Simulation sim(scene);
  BoundedRun r;
  for (long long i = 0; i < n; ++i) {
    r.steps = i + 1;
    if (!sim.step()) {
      r.finite = false;
      return r;
    }
    const double a = amp(sim.particles());
    r.max_amp = std::max(r.max_amp, a);
    if (!(a <= limit)) {
      r.bounded = false;
      return r;
    }
  }
  return r;
}

long long steps_for(double periods, double omega, double h) {
  return static_cast<long long>(std::ceil(periods * 2.0 * kPi / (omega * h)));
}

}  // namespace

OscillatorRun run_oscillator(IntegratorKind k, double ks, double m, double h, double periods, double amplitude_bound) {
  const double omega = std::sqrt(ks / m);
  const Scene s = oscillator_scene(k, ks, m, h);
  Simulation sim(s);
  OscillatorRun r;
  const long long n = steps_for(periods, omega, h);
  const double r0 = 1.0;  // released at rest 1 m from the anchor
  for (long long i = 0; i < n; ++i) {
    r.steps = i + 1;
    if (!sim.step()) {
      r.finite = false;
      break;
    }
    if (!(sim.particles().x[1].norm() <= amplitude_bound)) {
      r.bounded = false;
      break;
    }
  }
  if (r.finite) {
    const Vec3& x = sim.particles().x[1];
    const Vec3& v = sim.particles().v[1];
    const double rn = std::sqrt(x.squaredNorm() + v.squaredNorm() / (omega * omega));
    r.growth_per_step = std::exp(std::log(rn / r0) / static_cast<double>(r.steps));
  } else {
    r.growth_per_step = std::numeric_limits<double>::infinity();
  }
  return r;
}

StableStep oscillator_max_step(IntegratorKind k, double ks, double m, double periods, double amplitude_bound,
                               double rel_tol) {
  const double omega = std::sqrt(ks / m);
  return find_max_stable_step(
      [&](double h) {
        const OscillatorRun r = run_oscillator(k, ks, m, h, periods, amplitude_bound);
        return r.finite && r.bounded;
      },
      1.0 / omega, rel_tol);
}

namespace {

std::string sci(double x) {
  if (!std::isfinite(x)) return std::isnan(x) ? "NaN" : "inf";
  return fmt::format("{:.3g}", x);
}

double ulp_of(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()) - x; }

/// c = h omega at which (2 pi N / c) ln|R(ic)| = ln G: the largest step that a run of N periods
/// calls stable for a method whose amplification exceeds 1 at every c (Euler, midpoint).
double horizon_prediction(IntegratorKind k, double periods, double bound) {
  double lo = 1e-9, hi = 1.999;
  auto f = [&](double c) { return 2.0 * kPi * periods / c * std::log(amplification(k, c)) - std::log(bound); };
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

struct ExtremeRow {
  std::string group, label, measured, verdict;
};

/// Runs `fn`; an exception becomes a row saying what broke instead of ending the suite.
void guarded(std::vector<ExtremeRow>& rows, const std::string& group, const std::function<void()>& fn) {
  try {
    fn();
  } catch (const std::exception& e) {
    rows.push_back({group, "(the case itself)", "exception", fmt::format("broke: {}", e.what())});
  }
}

}  // namespace

namespace {

/// The suite's settings: tolerances from data/tolerances.json and the grids (smaller with --quick).
struct StabilityParams {
  double periods = 0, bound = 0, ratio_lo = 0, ratio_hi = 0, spread_max = 0, growth_rel = 0, horizon_lo = 0,
         horizon_hi = 0, offset_ulps = 0, near_zero_nonfinite = 0, zero_force_max = 0, rest_sink = 0, rest_jitter = 0,
         tunnel_wrong = 0;
  double rel_tol = 1e-6;  ///< bisection bracket, relative to h
  std::vector<double> ks_list, m_list;  ///< [N/m], [kg]
  std::vector<double> horizons;         ///< run lengths [periods] of the horizon table
};

StabilityParams stability_params(const SuiteContext& ctx) {
  const Tolerances& tol = *ctx.tolerances;
  StabilityParams P;
  P.periods = tol.get("/stability/periods");
  P.bound = tol.get("/stability/amplitude_bound");
  P.ratio_lo = tol.get("/stability/ratio_lo");
  P.ratio_hi = tol.get("/stability/ratio_hi");
  P.spread_max = tol.get("/stability/grid_spread");
  P.growth_rel = tol.get("/stability/growth_rel_error");
  P.horizon_lo = tol.get("/stability/horizon_ratio_lo");
  P.horizon_hi = tol.get("/stability/horizon_ratio_hi");
  P.offset_ulps = tol.get("/stability/offset_error_ulps_per_step");
  P.near_zero_nonfinite = tol.get("/stability/near_zero_nonfinite");
  P.zero_force_max = tol.get("/stability/zero_length_force");
  P.rest_sink = tol.get("/stability/rest_max_sink");
  P.rest_jitter = tol.get("/stability/rest_max_jitter");
  P.tunnel_wrong = tol.get("/stability/tunnel_wrong_side_steps");
  if (ctx.quick) {
    P.ks_list = {1e-2, 1e1, 1e4};
    P.m_list = {1e-3, 1e0, 1e3};
  } else {
    for (int e = -2; e <= 4; ++e) P.ks_list.push_back(std::pow(10.0, e));
    for (int e = -3; e <= 3; ++e) P.m_list.push_back(std::pow(10.0, e));
  }
  P.horizons = ctx.quick ? std::vector<double>{10, 30, 100} : std::vector<double>{10, 30, 100, 300};
  return P;
}

struct Theory {
  IntegratorKind k;
  double c;  ///< theoretical limit of h omega
};
const Theory kStableKinds[] = {{IntegratorKind::Symplectic, 2.0}, {IntegratorKind::RK4, 2.0 * std::sqrt(2.0)}};
const IntegratorKind kGrowers[] = {IntegratorKind::Euler, IntegratorKind::Midpoint};
const double kGrowthCs[] = {0.01, 0.1, 1.0};  ///< c = h omega of the growth table
constexpr std::size_t kExtremes = 5;            ///< offset, mass ratio, near-zero rest length, resting, tunnelling

/// The cases, in index order (the longest first, so the threads finish together):
///   0..4                 the five groups of extremes;
///   then the grid        stable kind x ks x m: the largest stable step of one cell;
///   then the horizons    grower x N periods: the "largest stable step" over N periods;
///   then the growth      grower x c x ks x m: one run of 20 periods at h = c / omega.
std::size_t stability_case_count(const StabilityParams& P) {
  const std::size_t cells = P.ks_list.size() * P.m_list.size();
  return kExtremes + 2 * cells + 2 * P.horizons.size() + 2 * std::size(kGrowthCs) * cells;
}

io::Json step_json(const StableStep& st) {
  return {{"found", st.found}, {"h", num(st.h)}, {"h_unstable", num(st.h_unstable)}, {"runs", st.runs}};
}

StableStep step_from_json(const io::Json& j) {
  StableStep st;
  st.found = j.at("found").get<bool>();
  st.h = get_num(j.at("h"));
  st.h_unstable = get_num(j.at("h_unstable"));
  st.runs = j.at("runs").get<int>();
  return st;
}

/// One group of extremes: {"rows":[[group, case, measured, verdict]], "checks":[...], "data":{...}}.
io::Json extreme_case(const StabilityParams& P, std::size_t which) {
  // The parameters the extremes use, by their names in the tolerance file's section.
  const double periods = P.periods, bound = P.bound, ratio_lo = P.ratio_lo, ratio_hi = P.ratio_hi,
               offset_ulps = P.offset_ulps, near_zero_nonfinite = P.near_zero_nonfinite,
               zero_force_max = P.zero_force_max, rest_sink = P.rest_sink, rest_jitter = P.rest_jitter,
               tunnel_wrong = P.tunnel_wrong, rel_tol = P.rel_tol;
  const auto& stable_kinds = kStableKinds;
  std::vector<ExtremeRow> rows;
  SuiteResult res;
  io::Json data = io::Json::object();
  switch (which) {
    case 0:
    // 3a. Coordinates offset by 1e6..1e8 m.
    guarded(rows, "offset", [&] {
      const double offsets[] = {1e6, 1e7, 1e8};
      double worst_ratio = 0.0;
      for (double O : offsets) {
        const Vec3 off(O, O, O);
        const double u = ulp_of(O);
        // Oscillators: ks = 4 N/m, m = 1 kg (omega = 2), rest length l, released stretched by a,
        // symplectic, h = 1e-3 s, 10 periods.
        struct Osc {
          double l, a;
        };
        for (const Osc o : {Osc{1.0, 0.1}, Osc{0.01, 1e-3}}) {
          auto make = [&](const Vec3& shift) {
            Scene s;
            s.dt = 1e-3;
            s.particles.add(shift, Vec3::Zero(), 0.0, 1.0, true);
            s.particles.add(shift + Vec3(o.l + o.a, 0, 0), Vec3::Zero(), 1.0, 1.0, false);
            s.forces.springs.push_back(Spring{0, 1, 4.0, o.l, 0.0});
            return s;
          };
          Simulation ref(make(Vec3::Zero())), sh(make(off));
          const long long n = std::llround(10.0 * kPi / 1e-3);
          double err = 0.0;
          bool finite = true;
          for (long long i = 0; i < n; ++i) {
            finite = ref.step() && sh.step() && finite;
            err = std::max(err, ((sh.particles().x[1] - off) - ref.particles().x[1]).cwiseAbs().maxCoeff());
          }
          const double per_step = err / (u * static_cast<double>(n));
          worst_ratio = std::max(worst_ratio, finite ? per_step : INFINITY);
          const double rel = err / o.a;
          rows.push_back({"offset", fmt::format("spring l = {:g} m, amplitude {:g} m, at {:g} m", o.l, o.a, O),
                          fmt::format("max error {} m = {:.3g} ulp({:g}) over {} steps ({:.2g} ulp/step); {:.2g} of the "
                                      "amplitude",
                                      sci(err), err / u, O, n, per_step, rel),
                          !finite ? "broke: non-finite"
                                  : (rel <= 1e-3 ? "ok: only storage rounding, within 1e-3 of the amplitude"
                                                 : fmt::format("degraded: positions are stored to ulp = {:.2g} m, {:.1g} "
                                                               "of the amplitude, each step",
                                                               u, u / o.a))});
        }
        // A particle dropped on a plane, both shifted.
        auto make_drop = [&](const Vec3& shift) {
          Scene s;
          s.dt = 1e-3;
          s.forces.gravity = Vec3(0, 0, -9.81);
          s.particles.add(shift + Vec3(0.1, 0.2, 1.0), Vec3(0.2, 0.1, 0.0), 1.0, 0.5, false);
          s.planes.push_back(make_bounded_plane(shift, Vec3::UnitZ(), Vec3::UnitX(), Vec2(1.0, 1.0), 0.5));
          return s;
        };
        Simulation ref(make_drop(Vec3::Zero())), sh(make_drop(off));
        const long long n = 3000;
        double err = 0.0, sink = 0.0;
        bool finite = true;
        for (long long i = 0; i < n; ++i) {
          finite = ref.step() && sh.step() && finite;
          err = std::max(err, ((sh.particles().x[0] - off) - ref.particles().x[0]).cwiseAbs().maxCoeff());
          sink = std::max(sink, -sh.scene().planes[0].side(sh.particles().x[0]));
        }
        const double per_step = err / (u * static_cast<double>(n));
        worst_ratio = std::max(worst_ratio, finite ? per_step : INFINITY);
        rows.push_back(
            {"offset", fmt::format("particle dropped 1 m on a plane (k = 0.5, friction 0.5), at {:g} m", O),
             fmt::format("max error {} m = {:.3g} ulp({:g}) over {} steps ({:.2g} ulp/step); max sink below the plane "
                         "{} m; {} contacts vs {} unshifted",
                         sci(err), err / u, O, n, per_step, sci(sink), sh.contacts().events, ref.contacts().events),
             !finite ? "broke: non-finite"
                     : (sink > 0.0 ? "broke: ended below the plane"
                                   : fmt::format("ok: {:.2g} of the 1 m drop, same contacts, never below the plane", err))});
      }
      res.checks.push_back(make_check("stability/extremes/offset_error_ulps_per_step", worst_ratio, 0.0, offset_ulps,
                                      "max |error vs unshifted| / (steps x ulp(offset)), worst case"));
    });
      break;
    case 1:
    // 3b. Mass ratios across a spring.
    guarded(rows, "mass ratio", [&] {
      struct Chain {
        std::string label;
        double m1, m2;
        bool anchored;  // anchor - m1 - m2 chain; otherwise a free pair m1 - m2
      };
      const double ks = 1.0;
      double rmin = INFINITY, rmax = -INFINITY;
      double h_equal[2] = {0, 0};
      int idx = 0;
      for (const Chain& ch : {Chain{"free pair 1 kg : 1 kg", 1.0, 1.0, false}, Chain{"free pair 1 kg : 1e-6 kg", 1.0, 1e-6, false},
                              Chain{"chain anchor - 1 kg - 1e-6 kg", 1.0, 1e-6, true}}) {
        Scene s;
        double omega_max;
        if (ch.anchored) {
          s.particles.add(Vec3::Zero(), Vec3::Zero(), 0.0, 1.0, true);
          s.particles.add(Vec3::Zero(), Vec3::Zero(), ch.m1, 1.0, false);
          s.particles.add(Vec3(1.0, 0, 0), Vec3::Zero(), ch.m2, 1.0, false);
          s.forces.springs.push_back(Spring{0, 1, ks, 0.0, 0.0});
          s.forces.springs.push_back(Spring{1, 2, ks, 0.0, 0.0});
          // Eigenvalues of M^-1 K, K = ks [[2, -1], [-1, 1]].
          const double T = 2.0 * ks / ch.m1 + ks / ch.m2, D = ks * ks / (ch.m1 * ch.m2);
          omega_max = std::sqrt(0.5 * (T + std::sqrt(T * T - 4.0 * D)));
        } else {
          s.particles.add(Vec3::Zero(), Vec3::Zero(), ch.m1, 1.0, false);
          s.particles.add(Vec3(1.0, 0, 0), Vec3::Zero(), ch.m2, 1.0, false);
          s.forces.springs.push_back(Spring{0, 1, ks, 0.0, 0.0});
          omega_max = std::sqrt(ks * (1.0 / ch.m1 + 1.0 / ch.m2));
        }
        // Amplitude: the largest spring extension (relative coordinates; the free pair's centre of
        // mass is at rest).
        auto amp = [&s](const Particles& p) {
          double a = 0.0;
          for (const Spring& sp : s.forces.springs) a = std::max(a, (p.x[sp.j] - p.x[sp.i]).norm());
          return a;
        };
        std::string measured;
        double row_min = INFINITY, row_max = -INFINITY;
        int kk = 0;
        for (const Theory& th : stable_kinds) {
          const StableStep st = find_max_stable_step(
              [&](double h) {
                Scene t = s;
                t.integrator = th.k;
                t.dt = h;
                const BoundedRun r = run_bounded(t, steps_for(periods, omega_max, h), amp, bound);
                return r.finite && r.bounded;
              },
              1.0 / omega_max, rel_tol);
          const double ratio = st.h * omega_max / th.c;
          rmin = std::min(rmin, ratio);
          rmax = std::max(rmax, ratio);
          row_min = std::min(row_min, ratio);
          row_max = std::max(row_max, ratio);
          if (idx == 0) h_equal[kk] = st.h;
          measured += fmt::format("{}{}: h_max = {} s, h_max omega_max = {:.5f} (/{:.3f} = {:.4f}){}", kk ? "; " : "",
                                  integrator_name(th.k), sci(st.h), st.h * omega_max, th.c, ratio,
                                  idx > 0 ? fmt::format(", {:.4g}x smaller than 1 kg : 1 kg", h_equal[kk] / st.h) : "");
          data["mass_ratio"][ch.label][integrator_name(th.k)] = {{"h_max", st.h}, {"omega_max", omega_max}, {"ratio", ratio}};
          ++kk;
        }
        rows.push_back({"mass ratio", ch.label + fmt::format(" (ks = 1 N/m, omega_max = {:.6g} 1/s)", omega_max), measured,
                        (row_min >= ratio_lo && row_max <= ratio_hi)
                            ? (idx == 0 ? "ok: reference" : "ok: stable, but the step is set by the light particle")
                            : "broke: limit differs from linear theory"});
        ++idx;
      }
      res.checks.push_back(make_check("stability/extremes/mass_ratio_min", rmin, ratio_lo, ratio_hi,
                                      "h_max omega_max / theory across mass ratios 1 and 1e6"));
      res.checks.push_back(make_check("stability/extremes/mass_ratio_max", rmax, ratio_lo, ratio_hi,
                                      "h_max omega_max / theory across mass ratios 1 and 1e6"));
    });
      break;
    case 2:
    // 3c. Near-zero rest lengths.
    guarded(rows, "near-zero rest length", [&] {
      long long nonfinite = 0;
      double zero_force = 0.0;
      const double ls[] = {1e-9, 1e-12, 1e-15};
      // Oscillating through the anchor (symplectic, ks = 1, m = 1, h = 0.01, 20 periods), amplitude
      // 1e-3 m, with a 1e-12 m sideways offset so the path passes beside the anchor too.
      auto through = [&](double l, double y0) {
        Scene s;
        s.dt = 0.01;
        s.particles.add(Vec3::Zero(), Vec3::Zero(), 0.0, 1.0, true);
        s.particles.add(Vec3(1e-3, y0, 0), Vec3::Zero(), 1.0, 1.0, false);
        s.forces.springs.push_back(Spring{0, 1, 1.0, l, 0.0});
        return s;
      };
      const long long n = std::llround(20 * 2 * kPi / 0.01);
      for (double y0 : {0.0, 1e-12}) {
        Simulation zero(through(0.0, y0));
        std::vector<std::unique_ptr<Simulation>> sims;  // a Simulation is not movable (its callbacks hold this)
        for (double l : ls) sims.push_back(std::make_unique<Simulation>(through(l, y0)));
        std::vector<double> dev(sims.size(), 0.0), amax(sims.size(), 0.0);
        std::vector<bool> fin(sims.size(), true);
        for (long long i = 0; i < n; ++i) {
          zero.step();
          for (std::size_t k = 0; k < sims.size(); ++k) {
            if (!fin[k]) continue;
            fin[k] = sims[k]->step();
            dev[k] = std::max(dev[k], (sims[k]->particles().x[1] - zero.particles().x[1]).norm());
            amax[k] = std::max(amax[k], sims[k]->particles().x[1].norm());
          }
        }
        for (std::size_t k = 0; k < sims.size(); ++k) {
          nonfinite += fin[k] ? 0 : 1;
          rows.push_back({"near-zero rest length",
                          fmt::format("l = {:g} m, oscillating 1 mm through the anchor{}", ls[k],
                                      y0 != 0.0 ? " (1e-12 m beside it)" : ""),
                          fmt::format("finite: {}; max |x| = {} m; max deviation from the l = 0 run {} m (l itself: {:g})",
                                      fin[k] ? "yes" : "NO", sci(amax[k]), sci(dev[k]), ls[k]),
                          fin[k] ? fmt::format("ok: finite; deviation {:.3g} l, proportional to l (the period changes by "
                                               "O(l/amplitude), a phase drift)",
                                               dev[k] / ls[k])
                                 : "broke: non-finite"});
        }
      }
      // Coincident ends: the engine skips the force (direction undefined), so a spring that should
      // push its ends l apart does nothing.
      for (double l : {1e-9, 1e-12, 1e-15, 0.0}) {
        Scene s;
        s.dt = 0.01;
        s.particles.add(Vec3(0.5, 0.5, 0.5), Vec3::Zero(), 0.0, 1.0, true);
        s.particles.add(Vec3(0.5, 0.5, 0.5), Vec3::Zero(), 1.0, 1.0, false);
        s.forces.springs.push_back(Spring{0, 1, 1.0, l, 0.0});
        std::vector<Vec3> f;
        accumulate_spring_forces(s.forces.springs, s.particles.x, s.particles.v, f);
        zero_force = std::max(zero_force, f[1].norm());
        Simulation sim(s);
        const bool ok = sim.run(1000);
        nonfinite += ok ? 0 : 1;
        const double moved = (sim.particles().x[1] - s.particles.x[1]).norm();
        rows.push_back({"near-zero rest length", fmt::format("l = {:g} m, both ends at the same point", l),
                        fmt::format("force {:g} N (exact 0: skipped); after 1000 steps finite: {}, moved {} m", f[1].norm(),
                                    ok ? "yes" : "NO", sci(moved)),
                        ok ? (l > 0.0 ? fmt::format("ok, documented limitation: should be pushed out to l, stays {:g} m short",
                                                    l)
                                      : "ok: at rest at its rest length")
                           : "broke: non-finite"});
      }
      // Separations below sqrt(DBL_MIN): |d|^2 is subnormal (1e-160) or underflows to 0 (1e-200).
      for (double d : {1e-160, 1e-200}) {
        std::vector<Spring> sp{Spring{0, 1, 1.0, 1e-15, 0.0}};
        std::vector<Vec3> x{Vec3::Zero(), Vec3(d, 0, 0)}, v{Vec3::Zero(), Vec3::Zero()}, f;
        accumulate_spring_forces(sp, x, v, f);
        const bool fin = f[0].allFinite() && f[1].allFinite();
        nonfinite += fin ? 0 : 1;
        rows.push_back({"near-zero rest length", fmt::format("l = 1e-15 m, ends {:g} m apart (|d|^2 {})", d,
                                                             d * d > 0.0 ? "subnormal" : "underflows to 0"),
                        fmt::format("force on the free end {} N (expected +{:g} N, pushing apart); finite: {}",
                                    sci(f[1].x()), 1e-15, fin ? "yes" : "NO"),
                        !fin ? "broke: non-finite"
                             : (f[1].x() > 0.0 ? fmt::format("ok: direction kept (|u| - 1 = {:.1e})",
                                                             std::abs(f[1].x()) / (1e-15 - d) - 1.0)
                                               : "ok, documented limitation: |d| = 0 in floating point, force skipped")});
      }
      res.checks.push_back(make_check("stability/extremes/near_zero_nonfinite", static_cast<double>(nonfinite), 0.0,
                                      near_zero_nonfinite, "runs or forces with NaN/Inf among near-zero rest lengths"));
      res.checks.push_back(make_check("stability/extremes/zero_length_force", zero_force, 0.0, zero_force_max,
                                      "force of a spring whose ends coincide: skipped, exactly 0"));
    });
      break;
    case 3:
    // 3d. Resting on a plane at zero speed.
    guarded(rows, "resting contact", [&] {
      const long long n = 100000;
      const IntegratorKind all[] = {IntegratorKind::Euler, IntegratorKind::Symplectic, IntegratorKind::Midpoint,
                                    IntegratorKind::RK4};
      double sink_all = 0.0, jitter_all = 0.0;
      for (double O : {0.0, 1e6}) {
        for (IntegratorKind k : all) {
          if (O != 0.0 && k != IntegratorKind::Symplectic) continue;
          Scene s;
          s.integrator = k;
          s.dt = 0.01;
          s.forces.gravity = Vec3(0, 0, -9.81);
          s.particles.add(Vec3(O + 0.1, O + 0.2, O), Vec3::Zero(), 1.0, 0.5, false);
          s.planes.push_back(make_bounded_plane(Vec3(O, O, O), Vec3::UnitZ(), Vec3::UnitX(), Vec2(1.0, 1.0), 0.5));
          Simulation sim(s);
          double sink = 0.0, jitter = 0.0, vmax = 0.0;
          bool ok = true;
          for (long long i = 0; i < n && ok; ++i) {
            ok = sim.step();
            const double z = s.planes[0].side(sim.particles().x[0]);
            sink = std::max(sink, -z);
            jitter = std::max(jitter, z);
            vmax = std::max(vmax, sim.particles().v[0].norm());
          }
          const double drift = (sim.particles().x[0] - s.particles.x[0]).norm();
          sink_all = std::max(sink_all, ok ? sink : INFINITY);
          jitter_all = std::max(jitter_all, ok ? jitter : INFINITY);
          rows.push_back(
              {"resting contact",
               fmt::format("{}, at rest on a plane{}, 1e5 steps of 0.01 s", integrator_name(k),
                           O != 0.0 ? fmt::format(" at {:g} m", O) : ""),
               fmt::format("max sink {} m, max height above {} m, max |v| {} m/s, drift {} m, resting: {}", sci(sink),
                           sci(jitter), sci(vmax), sci(drift), sim.resting_contacts().empty() ? "no" : "yes"),
               !ok ? "broke: non-finite"
                   : (sink > 0.0 ? "broke: sank below the plane"
                                 : (jitter <= rest_jitter ? "ok: still" : "degraded: jitters above the plane"))});
        }
      }
      res.checks.push_back(make_check("stability/extremes/rest_max_sink", sink_all, 0.0, rest_sink,
                                      "max depth below the plane over 1e5 resting steps, any integrator"));
      res.checks.push_back(make_check("stability/extremes/rest_max_jitter", jitter_all, 0.0, rest_jitter,
                                      "max height above the plane over 1e5 resting steps, any integrator"));
    });
      break;
    case 4:
    // 3e. Very long steps toward a thin bounded plane.
    guarded(rows, "tunnelling", [&] {
      const IntegratorKind all[] = {IntegratorKind::Euler, IntegratorKind::Symplectic, IntegratorKind::Midpoint,
                                    IntegratorKind::RK4};
      long long wrong_all = 0;
      for (double speed : {1.0, 1000.0}) {
        for (double dt : {1e-3, 1e-2, 0.1, 1.0, 10.0}) {
          std::string measured;
          long long wrong_row = 0;
          for (IntegratorKind k : all) {
            Scene s;
            s.integrator = k;
            s.dt = dt;
            s.forces.gravity = Vec3(0, 0, -9.81);
            s.particles.add(Vec3(0.1, 0.2, 1.0), Vec3(0, 0, -speed), 1.0, 0.5, false);
            // A 1 m x 1 m plane of zero thickness.
            s.planes.push_back(make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), Vec2(0.5, 0.5), 0.5));
            Simulation sim(s);
            const long long n = std::max<long long>(20, std::llround(20.0 / dt));
            long long wrong = 0;
            double zmin = INFINITY;
            bool ok = true;
            for (long long i = 0; i < n && ok; ++i) {
              ok = sim.step();
              const double z = sim.particles().x[0].z();
              zmin = std::min(zmin, z);
              if (z < 0.0) ++wrong;
            }
            if (!ok) ++wrong;
            wrong_row += wrong;
            measured += fmt::format("{}{}: {} wrong-side steps, min z {}, {} contacts", measured.empty() ? "" : "; ",
                                    integrator_name(k), wrong, sci(zmin), sim.contacts().events);
          }
          wrong_all += wrong_row;
          rows.push_back({"tunnelling", fmt::format("dt = {:g} s, falling at {:g} m/s from 1 m, 20 s", dt, speed), measured,
                          wrong_row == 0 ? "ok: never on the wrong side" : "broke: tunnelled"});
        }
      }
      res.checks.push_back(make_check("stability/extremes/tunnel_wrong_side_steps", static_cast<double>(wrong_all), 0.0,
                                      tunnel_wrong, "steps ending below a thin plane, any dt up to 10 s, any integrator"));
    });
      break;
    default:
      break;
  }
  io::Json jrows = io::Json::array(), jchecks = io::Json::array();
  for (const ExtremeRow& r : rows) jrows.push_back({r.group, r.label, r.measured, r.verdict});
  for (const Check& c : res.checks) jchecks.push_back(check_json(c));
  return {{"rows", jrows}, {"checks", jchecks}, {"data", data}};
}

io::Json stability_case(const StabilityParams& P, std::size_t k) {
  if (k < kExtremes) return extreme_case(P, k);
  const std::size_t nks = P.ks_list.size(), nm = P.m_list.size(), cells = nks * nm;
  std::size_t i = k - kExtremes;
  if (i < 2 * cells) {  // grid: kind, ks, m
    const Theory& th = kStableKinds[i / cells];
    const double ks = P.ks_list[(i % cells) / nm], m = P.m_list[i % nm];
    return step_json(oscillator_max_step(th.k, ks, m, P.periods, P.bound, P.rel_tol));
  }
  i -= 2 * cells;
  if (i < 2 * P.horizons.size()) {  // horizon: grower, N
    const IntegratorKind g = kGrowers[i / P.horizons.size()];
    return step_json(oscillator_max_step(g, 1.0, 1.0, P.horizons[i % P.horizons.size()], P.bound, 1e-4));
  }
  i -= 2 * P.horizons.size();  // growth: grower, c, ks, m
  const std::size_t per_grower = std::size(kGrowthCs) * cells;
  const IntegratorKind g = kGrowers[i / per_grower];
  const double c = kGrowthCs[(i % per_grower) / cells];
  const double ks = P.ks_list[(i % cells) / nm], m = P.m_list[i % nm];
  const double omega = std::sqrt(ks / m);
  const OscillatorRun r = run_oscillator(g, ks, m, c / omega, 20.0, P.bound);
  return {{"growth_per_step", num(r.growth_per_step)}, {"finite", r.finite}};
}

SuiteResult stability_assemble(const StabilityParams& P, const std::vector<io::Json>& results) {
  SuiteResult res;
  res.name = "stability";
  // The parameters the tables and checks use, by their names in the tolerance file's section.
  const double periods = P.periods, bound = P.bound, ratio_lo = P.ratio_lo, ratio_hi = P.ratio_hi,
               spread_max = P.spread_max, growth_rel = P.growth_rel, horizon_lo = P.horizon_lo,
               horizon_hi = P.horizon_hi, rel_tol = P.rel_tol;
  const auto& stable_kinds = kStableKinds;
  const std::vector<double>& ks_list = P.ks_list;
  const std::vector<double>& m_list = P.m_list;
  io::Json data = io::Json::object();

  std::string md = fmt::format(
      "The oscillator: a particle of mass m on a zero-rest-length spring of stiffness ks to a pinned particle "
      "(force -ks x, exactly linear in every direction), released at rest 1 m from the anchor; omega = sqrt(ks/m). "
      "**Stable at h** means: over {0:g} periods (2 pi/omega each) at step h the run stays finite and |x| never "
      "exceeds {1:g} times its initial value. The largest stable h is found by a deterministic bisection on h: "
      "start at h = 1/omega, double (or halve) to bracket, then bisect at the midpoint until the bracket is "
      "{2:g} of h wide. Grid: ks in {3:g}..{4:g} N/m ({5} values) x m in {6:g}..{7:g} kg ({8} values).\n\n"
      "Theory (linear stability of x'' = -omega^2 x, c = h omega): symplectic Euler's update has trace 2 - c^2 and "
      "determinant 1, so it is stable for c < 2; RK4's amplification |R(ic)|^2 = 1 - c^6/72 + c^8/576 is <= 1 "
      "for c <= 2 sqrt 2 = 2.828. Explicit Euler (|R|^2 = 1 + c^2) and midpoint (|R|^2 = 1 + c^4/4) amplify "
      "every oscillation at **every** h > 0: they have no stable step on an undamped oscillator, so the suite "
      "reports their measured growth per period instead. Near c = 2 symplectic Euler's invariant ellipse "
      "stretches: |x| peaks at 2/sqrt(4 - c^2) times the initial amplitude, so a bound of {1:g}x puts the "
      "measured limit at 2 sqrt(1 - 1/{1:g}^2) (a bound of 10x would have stopped it at 1.990).\n\n",
      periods, bound, rel_tol, ks_list.front(), ks_list.back(), ks_list.size(), m_list.front(), m_list.back(),
      m_list.size());

  // ---- 1. Max stable step over the grid -------------------------------------------------------
  std::size_t grid_k = kExtremes;  // the grid cases follow the extremes
  md += "### Largest stable step, h_max omega (theory: symplectic 2, rk4 2.828)\n\n";
  for (const Theory& th : stable_kinds) {
    const char* name = integrator_name(th.k);
    std::string tab = fmt::format("**{}**: h_max omega by cell (h_max [s] in brackets)\n\n| ks \\ m |", name);
    for (double m : m_list) tab += fmt::format(" {:g} kg |", m);
    tab += "\n|---|";
    for (std::size_t j = 0; j < m_list.size(); ++j) tab += "---:|";
    tab += "\n";
    double rmin = INFINITY, rmax = -INFINITY, cmin = INFINITY, cmax = -INFINITY;
    int runs = 0;
    io::Json cells = io::Json::array();
    for (double ks : ks_list) {
      tab += fmt::format("| {:g} N/m |", ks);
      for (double m : m_list) {
        const double omega = std::sqrt(ks / m);
        const StableStep st = step_from_json(results.at(grid_k++));
        runs += st.runs;
        const double c = st.found ? st.h * omega : std::nan("");
        rmin = std::min(rmin, c / th.c);
        rmax = std::max(rmax, c / th.c);
        cmin = std::min(cmin, c);
        cmax = std::max(cmax, c);
        tab += fmt::format(" {:.6f} ({}) |", c, sci(st.h));
        cells.push_back({{"ks", ks}, {"m", m}, {"h_max", st.h}, {"h_omega", c}, {"runs", st.runs}});
      }
      tab += "\n";
    }
    md += tab + fmt::format("\nmeasured / theory: min {:.6f}, max {:.6f}; spread over the grid (max/min - 1) {:.2e}; "
                            "{} simulation runs.\n\n",
                            rmin, rmax, cmax / cmin - 1.0, runs);
    res.checks.push_back(make_check(fmt::format("stability/{}/h_omega_ratio_min", name), rmin, ratio_lo, ratio_hi,
                                    "min over the grid of measured h_max omega / theory"));
    res.checks.push_back(make_check(fmt::format("stability/{}/h_omega_ratio_max", name), rmax, ratio_lo, ratio_hi,
                                    "max over the grid of measured h_max omega / theory"));
    res.checks.push_back(make_check(fmt::format("stability/{}/grid_spread", name), cmax / cmin - 1.0, 0.0, spread_max,
                                    "h_max omega depends on h omega only: max/min - 1 over the grid"));
    data["max_step"][name] = {{"theory_h_omega", th.c}, {"ratio_min", rmin}, {"ratio_max", rmax}, {"cells", cells}};
  }

  // ---- 2. Growth per period of Euler and midpoint ---------------------------------------------
  md += "### Explicit Euler and midpoint: no stable step, growth per period\n\n"
        "The norm r = sqrt(|x|^2 + |v|^2/omega^2) after n steps (20 periods, or until |x| passes the bound) gives "
        "the measured growth per step (r_n/r_0)^(1/n), raised to the 2 pi/c steps of a period; theory "
        "|R(ic)|^(2 pi/c). Range over the grid; rel. error = |ln measured / ln theory - 1|, worst cell.\n\n"
        "| integrator | c = h omega | theory growth / period | measured min | measured max | rel. error |\n"
        "|---|---:|---:|---:|---:|---:|\n";
  const auto& growers = kGrowers;
  const auto& cs = kGrowthCs;
  std::size_t growth_k = kExtremes + 2 * ks_list.size() * m_list.size() + 2 * P.horizons.size();
  for (IntegratorKind k : growers) {
    const char* name = integrator_name(k);
    double worst = 0.0, gmin_all = INFINITY;
    for (double c : cs) {
      const double theory = std::pow(amplification(k, c), 2.0 * kPi / c);
      double gmin = INFINITY, gmax = -INFINITY, err = 0.0;
      for (std::size_t cell = 0; cell < ks_list.size() * m_list.size(); ++cell) {  // ks (outer) x m
        const io::Json& jr = results.at(growth_k++);
        OscillatorRun r;
        r.growth_per_step = get_num(jr.at("growth_per_step"));
        r.finite = jr.at("finite").get<bool>();
        const double g = std::pow(r.growth_per_step, 2.0 * kPi / c);
        gmin = std::min(gmin, g);
        gmax = std::max(gmax, g);
        err = std::max(err, std::abs(std::log(g) / std::log(theory) - 1.0));
        if (!r.finite) err = INFINITY;
      }
      worst = std::max(worst, err);
      gmin_all = std::min(gmin_all, gmin);
      md += fmt::format("| {} | {:g} | {:.9g} | {:.9g} | {:.9g} | {:.1e} |\n", name, c, theory, gmin, gmax, err);
      data["growth"][name].push_back({{"c", c}, {"theory", theory}, {"min", gmin}, {"max", gmax}, {"rel_error", err}});
    }
    res.checks.push_back(make_check(fmt::format("stability/{}/growth_rel_error", name), worst, 0.0, growth_rel,
                                    "measured log growth per period vs theory, worst over grid and c"));
  }

  // Horizon: the "largest stable step" of a method with no stable step shrinks with the run length.
  const std::vector<double>& horizons = P.horizons;
  std::size_t horizon_k = kExtremes + 2 * ks_list.size() * m_list.size();
  md += fmt::format(
      "\nWhat the bisection reports for them depends on how long one looks: with the same definition "
      "(|x| <= {:g}x over N periods; ks = 1 N/m, m = 1 kg) the \"largest stable step\" shrinks as N grows "
      "(Euler about ln({:g})/(pi N), midpoint about (4 ln({:g})/(pi N))^(1/3)), so no step is stable for all time. "
      "Predicted: the c at which (2 pi N/c) ln|R(ic)| = ln {:g}.\n\n"
      "| integrator | N periods | measured h omega | predicted | measured/predicted |\n|---|---:|---:|---:|---:|\n",
      bound, bound, bound, bound);
  for (IntegratorKind k : growers) {
    double worst_lo = INFINITY, worst_hi = -INFINITY;
    for (double N : horizons) {
      const StableStep st = step_from_json(results.at(horizon_k++));
      const double pred = horizon_prediction(k, N, bound);
      const double ratio = st.found ? st.h / pred : std::nan("");
      worst_lo = std::min(worst_lo, ratio);
      worst_hi = std::max(worst_hi, ratio);
      md += fmt::format("| {} | {:g} | {:.5f} | {:.5f} | {:.4f} |\n", integrator_name(k), N, st.h, pred, ratio);
      data["horizon"][integrator_name(k)].push_back({{"periods", N}, {"measured", st.h}, {"predicted", pred}});
    }
    res.checks.push_back(make_check(fmt::format("stability/{}/horizon_ratio_min", integrator_name(k)), worst_lo,
                                    horizon_lo, horizon_hi, "horizon-limited step, measured / predicted"));
    res.checks.push_back(make_check(fmt::format("stability/{}/horizon_ratio_max", integrator_name(k)), worst_hi,
                                    horizon_lo, horizon_hi, "horizon-limited step, measured / predicted"));
  }

  // ---- 3. Extremes ------------------------------------------------------------------------------
  std::vector<ExtremeRow> rows;
  for (std::size_t x = 0; x < kExtremes; ++x) {
    const io::Json& jr = results.at(x);
    for (const auto& r : jr.at("rows"))
      rows.push_back({r.at(0).get<std::string>(), r.at(1).get<std::string>(), r.at(2).get<std::string>(),
                      r.at(3).get<std::string>()});
    for (const auto& c : jr.at("checks")) res.checks.push_back(check_from_json(c));
    for (auto it = jr.at("data").begin(); it != jr.at("data").end(); ++it) data[it.key()] = it.value();
  }
  std::string notes;
  notes +=
      "**Offsets.** A spring's x_j - x_i is exact when both ends are near the same large offset (Sterbenz), and so is "
      "a plane's side test p - position; what is lost is the storage of positions: at 10^8 m a double holds "
      "positions to ulp = 1.5e-8 m, and each step's x += h v rounds to it. The error against the unshifted run is "
      "therefore a sum of per-step roundings, bounded by about one ulp of the offset per step (checked), and it "
      "matters in proportion to ulp/amplitude: negligible for a 1 m spring, visible for a 1 cm spring with 1 mm "
      "motion.\n\n";

  notes += "**Mass ratios.** Nothing breaks numerically at 1e6, but the largest stable step is that of the fastest "
           "mode, omega_max^2 = ks (1/m1 + 1/m2) for a free pair: the light particle sets it, 1/sqrt(5e5) = 1/707 of "
           "the equal-mass pair's. A cloth with one very light node pays that price for the whole cloth.\n\n";

  notes += "**Near-zero rest lengths.** No NaN anywhere: the force is ks (|d| - l) d/|d| and the engine skips a spring "
           "whose |d| is 0, the one place the direction is undefined. The cost of that rule is visible: a spring of rest "
           "length l > 0 whose ends coincide exerts nothing, and the ends stay l short of rest (a 1e-9 m error here). "
           "|d| is computed as sqrt(|d|^2), which underflows to 0 below about 1.5e-162 m, where the same rule applies.\n\n";

  notes += "**Resting contact.** The first step's free fall crosses the plane from on it, the bisection finds the "
           "contact at once, |vn| is below the static threshold and the contact becomes resting: the plane then "
           "cancels the normal acceleration and the particle is still, bit for bit, for the rest of the run.\n\n";

  notes += "**Tunnelling.** The plane test works on the step's whole segment p1 -> p2 and each particle remembers its "
           "side, so step length does not matter: even a 10 s step that would carry the particle kilometres past the "
           "plane is bisected to the contact and answered there.\n\n";

  md += "\n### Extremes\n\n| group | case | measured | verdict |\n|---|---|---|---|\n";
  for (const ExtremeRow& r : rows) {
    md += fmt::format("| {} | {} | {} | {} |\n", r.group, r.label, r.measured, r.verdict);
    data["extremes"].push_back({{"group", r.group}, {"case", r.label}, {"measured", r.measured}, {"verdict", r.verdict}});
  }
  md += "\nDegenerate and near-degenerate triangles in self-collision are covered elsewhere.\n\n" + notes;
  res.markdown = md;
  res.data = data;
  return res;
}

}  // namespace

Sweep stability_sweep(const SuiteContext& ctx) {
  auto P = std::make_shared<const StabilityParams>(stability_params(ctx));
  Sweep s;
  s.cases = stability_case_count(*P);
  s.run_case = [P](std::size_t k) { return stability_case(*P, k); };
  s.assemble = [P](const std::vector<io::Json>& results) { return stability_assemble(*P, results); };
  return s;
}

SuiteResult run_stability_suite(const SuiteContext& ctx) { return run_sweep(&stability_sweep, ctx, "stability"); }

}  // namespace tecido::suites
