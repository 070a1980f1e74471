#include "comparisons/suites/order_suite.h"

#include "comparisons/io/atomic_file.h"
#include "comparisons/io/gnuplot.h"
#include "core/dynamics/simulation.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <functional>

namespace tecido::suites {

OrderFit fit_order(const std::vector<double>& h, const std::vector<double>& e, double floor, double too_big,
                   double agree, int min_halvings) {
  OrderFit f;
  const int n = static_cast<int>(e.size());
  std::vector<bool> ok(n);
  for (int k = 0; k < n; ++k) {
    ok[k] = std::isfinite(e[k]) && e[k] < too_big && e[k] > floor;
    if (std::isfinite(e[k]) && e[k] <= floor && f.roundoff_below_h == 0.0) {
      // errors at and below this h are round-off
      f.roundoff_below_h = h[k];
    }
    if ((!std::isfinite(e[k]) || e[k] >= too_big)) f.unstable_above_h = std::max(f.unstable_above_h, h[k]);
  }
  f.observed.assign(std::max(0, n - 1), std::nan(""));
  for (int k = 0; k + 1 < n; ++k)
    if (ok[k] && ok[k + 1]) f.observed[k] = std::log2(e[k] / e[k + 1]);
  // Longest run of defined halvings whose orders agree step to step.
  int best_a = -1, best_b = -1;
  for (int a = 0; a + 1 < n; ++a) {
    if (!std::isfinite(f.observed[a])) continue;
    int b = a;
    while (b + 1 < n - 1 && std::isfinite(f.observed[b + 1]) && std::abs(f.observed[b + 1] - f.observed[b]) <= agree) ++b;
    if (b - a > best_b - best_a) {
      best_a = a;
      best_b = b;
    }
  }
  if (best_a < 0 || best_b - best_a + 1 < min_halvings) return f;
  f.first = best_a;
  f.last = best_b + 1;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const int m = f.last - f.first + 1;
  for (int k = f.first; k <= f.last; ++k) {
    const double x = std::log(h[k]), y = std::log(e[k]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  f.slope = (m * sxy - sx * sy) / (m * sxx - sx * sx);
  return f;
}

namespace {

struct Problem {
  std::string name;
  std::string about;
  Scene scene;
  double T;
  double scale;  // size of the solution, for the instability and round-off thresholds
  std::function<std::vector<Vec3>(double)> exact;
};

std::vector<Problem> problems() {
  std::vector<Problem> out;
  {  // Harmonic oscillator: x'' = -(k/m)(x - l).
    Problem p{"harmonic", "one spring (ks = 4 N/m, l = 1 m) to a pinned particle, m = 1 kg, released 0.5 m stretched: x = 1 + 0.5 cos 2t", {}, 4.0, 1.0, {}};
    p.scene.particles.add(Vec3::Zero(), Vec3::Zero(), 0.0, 1.0, true);
    p.scene.particles.add(Vec3(1.5, 0, 0), Vec3::Zero(), 1.0, 1.0, false);
    p.scene.forces.springs.push_back(Spring{0, 1, 4.0, 1.0, 0.0});
    p.exact = [](double t) { return std::vector<Vec3>{Vec3::Zero(), Vec3(1.0 + 0.5 * std::cos(2.0 * t), 0, 0)}; };
    out.push_back(p);
  }
  {  // Damped: m x'' = -k (x - l) - c x'.
    const double m = 1.0, k = 4.0, c = 0.4, A = 0.5;
    const double g = c / (2 * m), wd = std::sqrt(k / m - g * g), B = g * A / wd;
    Problem p{"damped", "the same oscillator with linear air drag c = 0.4 kg/s (underdamped, gamma = 0.2 1/s)", {}, 4.0, 1.0, {}};
    p.scene.particles.add(Vec3::Zero(), Vec3::Zero(), 0.0, 1.0, true);
    p.scene.particles.add(Vec3(1.5, 0, 0), Vec3::Zero(), m, 1.0, false);
    p.scene.forces.springs.push_back(Spring{0, 1, k, 1.0, 0.0});
    p.scene.forces.air_drag = c;
    p.exact = [=](double t) {
      return std::vector<Vec3>{Vec3::Zero(), Vec3(1.0 + std::exp(-g * t) * (A * std::cos(wd * t) + B * std::sin(wd * t)), 0, 0)};
    };
    out.push_back(p);
  }
  {  // Projectile with linear drag: v = vinf + (v0 - vinf) e^{-ct/m}, vinf = m g / c.
    const double m = 2.0, c = 0.5;
    const Vec3 g(0, 0, -9.81), v0(3, 0, 5), x0(0, 0, 0);
    const Vec3 vinf = m * g / c;
    Problem p{"projectile-drag", "m = 2 kg thrown at (3, 0, 5) m/s under gravity with linear drag c = 0.5 kg/s", {}, 4.0, 10.0, {}};
    p.scene.particles.add(x0, v0, m, 1.0, false);
    p.scene.forces.gravity = g;
    p.scene.forces.air_drag = c;
    p.exact = [=](double t) {
      return std::vector<Vec3>{x0 + vinf * t + (v0 - vinf) * (m / c) * (1.0 - std::exp(-c * t / m))};
    };
    out.push_back(p);
  }
  {  // Two free particles joined by a spring, moving along the spring.
    const double m1 = 1.0, m2 = 2.0, k = 9.0, l = 1.0;
    const double M = m1 + m2, mu = m1 * m2 / M, w = std::sqrt(k / mu);
    const Vec3 x1(0, 0, 0), x2(1.2, 0, 0), v1(0.5, 0, 0), v2(-0.1, 0, 0);
    const Vec3 X0 = (m1 * x1 + m2 * x2) / M, V = (m1 * v1 + m2 * v2) / M;
    const double d0 = 1.2, dv0 = v2.x() - v1.x();
    Problem p{"two-body-spring", "m1 = 1 kg and m2 = 2 kg joined by ks = 9 N/m, l = 1 m, oscillating along the spring while the centre of mass drifts", {}, 4.0, 1.0, {}};
    p.scene.particles.add(x1, v1, m1, 1.0, false);
    p.scene.particles.add(x2, v2, m2, 1.0, false);
    p.scene.forces.springs.push_back(Spring{0, 1, k, l, 0.0});
    p.exact = [=](double t) {
      const double d = l + (d0 - l) * std::cos(w * t) + dv0 / w * std::sin(w * t);
      const Vec3 X = X0 + V * t;
      return std::vector<Vec3>{X - Vec3(m2 / M * d, 0, 0), X + Vec3(m1 / M * d, 0, 0)};
    };
    out.push_back(p);
  }
  return out;
}

struct Sample {
  double h, error, seconds;
};

Sample run_once(const Problem& p, IntegratorKind k, double h) {
  Scene s = p.scene;
  s.integrator = k;
  s.dt = h;
  const long long n = std::llround(p.T / h);
  Simulation sim(s);
  const auto t0 = std::chrono::steady_clock::now();
  sim.run(n);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto exact = p.exact(sim.time());
  double err = 0.0;
  for (std::size_t i = 0; i < exact.size(); ++i) err = std::max(err, (sim.particles().x[i] - exact[i]).norm());
  if (sim.instability()) err = std::numeric_limits<double>::infinity();
  return {h, err, secs};
}

double expected_order(IntegratorKind k) {
  switch (k) {
    case IntegratorKind::Euler:
    case IntegratorKind::Symplectic: return 1.0;
    case IntegratorKind::Midpoint: return 2.0;
    case IntegratorKind::RK4: return 4.0;
  }
  return 0.0;
}

}  // namespace

SuiteResult run_order_suite(const SuiteContext& ctx) {
  SuiteResult res;
  res.name = "order";
  const Tolerances& tol = *ctx.tolerances;
  const double band = tol.get("/order/band");
  const double floor_rel = tol.get("/order/roundoff_floor");
  const double too_big_rel = tol.get("/order/too_big");
  const int halvings = ctx.quick ? 9 : 12;
  const double h0 = 0.25;
  const IntegratorKind kinds[] = {IntegratorKind::Euler, IntegratorKind::Symplectic, IntegratorKind::Midpoint,
                                  IntegratorKind::RK4};
  const std::string dir = ctx.out_dir + "/order";

  std::string md = fmt::format(
      "Global position error at T against the analytic solution, for h = {} s halved {} times. The observed order "
      "of each halving is log2(e(h)/e(h/2)); the fitted order is the least-squares slope of log e against log h over "
      "the asymptotic range, found as the longest run of halvings whose observed orders agree (within 0.1 from one halving to the next) with "
      "errors between the round-off floor ({:g} x scale) and the instability/pre-asymptotic limit ({:g} x scale). "
      "Checks: fitted order within ±{} of 1 (euler), 1 (symplectic), 2 (midpoint), 4 (rk4).\n\n",
      h0, halvings, floor_rel, too_big_rel, band);
  io::Json data = io::Json::object();
  std::string head_to_head =
      "### Euler versus midpoint (the seed's question)\n\nAt equal step h = 1/64 s, and at equal cost (midpoint "
      "pays two force evaluations a step, so it gets 2h for Euler's h):\n\n"
      "| problem | e_euler(h) | e_midpoint(h) | ratio at equal h | e_midpoint(2h) | ratio at equal cost |\n"
      "|---|---:|---:|---:|---:|---:|\n";

  for (const Problem& p : problems()) {
    md += fmt::format("### {}\n\n{}; T = {} s.\n\n", p.name, p.about, p.T);
    md += "| integrator | fitted order | range h | observed orders per halving | round-off below h | excluded above h |\n|---|---:|---|---|---:|---:|\n";
    std::vector<std::vector<Sample>> all;
    std::string dat;
    for (IntegratorKind k : kinds) {
      std::vector<Sample> samples;
      std::vector<double> hs, es;
      for (int j = 0; j <= halvings; ++j) {
        const double h = h0 / std::pow(2.0, j);
        samples.push_back(run_once(p, k, h));
        hs.push_back(h);
        es.push_back(samples.back().error);
      }
      const OrderFit fit = fit_order(hs, es, floor_rel * p.scale, too_big_rel * p.scale);
      std::string obs;
      for (double o : fit.observed) obs += std::isfinite(o) ? fmt::format("{:.2f} ", o) : "– ";
      const std::string range = fit.first >= 0 ? fmt::format("{:.3g} … {:.3g}", hs[fit.first], hs[fit.last]) : "none";
      md += fmt::format("| {} | {:.3f} | {} | {}| {} | {} |\n", integrator_name(k), fit.slope, range, obs,
                        fit.roundoff_below_h > 0 ? fmt::format("{:.3g}", fit.roundoff_below_h) : "–",
                        fit.unstable_above_h > 0 ? fmt::format("{:.3g}", fit.unstable_above_h) : "–");
      const double want = expected_order(k);
      res.checks.push_back(make_check(fmt::format("order/{}/{}", p.name, integrator_name(k)), fit.slope, want - band,
                                      want + band));
      io::Json js = io::Json::array();
      for (const Sample& s : samples) js.push_back({{"h", s.h}, {"error", std::isfinite(s.error) ? io::Json(s.error) : io::Json(nullptr)}});
      data[p.name][integrator_name(k)] = {{"samples", js},
                                          {"fitted_order", std::isfinite(fit.slope) ? io::Json(fit.slope) : io::Json(nullptr)},
                                          {"range", fit.first >= 0 ? io::Json({hs[fit.first], hs[fit.last]}) : io::Json(nullptr)}};
      dat += fmt::format("# {}\n", integrator_name(k));
      for (const Sample& s : samples)
        if (std::isfinite(s.error) && s.error > 0) dat += fmt::format("{:.17g} {:.17g} {:.17g}\n", s.h, s.error, s.seconds);
      dat += "\n\n";
      all.push_back(samples);
    }
    // Euler (index 0) vs midpoint (index 2) at h = h0/16 = 1/64.
    const int j = 4;
    const double ee = all[0][j].error, em = all[2][j].error, em2 = all[2][j - 1].error;
    head_to_head += fmt::format("| {} | {:.3e} | {:.3e} | {:.3g} | {:.3e} | {:.3g} |\n", p.name, ee, em, ee / em, em2, ee / em2);
    io::write_file_atomic(dir + "/" + p.name + ".dat", dat);
    if (ctx.gnuplot) {
      // One plot command per integrator block (blocks are separated by two blank lines).
      const std::string titles[] = {"euler", "symplectic", "midpoint", "rk4"};
      std::string plot_h = "plot ", plot_t = "plot ";
      for (int i = 0; i < 4; ++i) {
        plot_h += fmt::format("{}'{}.dat' index {} using 1:2 with linespoints title '{}'", i ? ", " : "", p.name, i, titles[i]);
        plot_t += fmt::format("{}'{}.dat' index {} using 3:2 with linespoints title '{}'", i ? ", " : "", p.name, i, titles[i]);
      }
      const std::string s2 = fmt::format(
          "set terminal svg size 900,380 dynamic font 'sans,11'\nset output '{0}.svg'\nset multiplot layout 1,2 title '{0}'\n"
          "set logscale xy\nset format xy '10^{{%L}}'\nset key bottom right\nset grid\n"
          "set xlabel 'step h [s]'\nset ylabel 'error at T [m]'\n{1}\n"
          "set xlabel 'wall time [s]'\n{2}\nunset multiplot\n",
          p.name, plot_h, plot_t);
      if (io::run_gnuplot(dir, p.name, s2)) {
        res.plots.push_back("order/" + p.name + ".svg");
        md += fmt::format("\n![{0}: error vs h and error vs wall time](order/{0}.svg)\n", p.name);
      }
    }
    md += "\n";
  }
  res.markdown = md + head_to_head + "\nAt equal h midpoint is far more accurate; at equal cost it still wins "
                                   "once h is in the asymptotic range, since its error falls as h^2.\n";
  res.data = data;
  return res;
}

}  // namespace tecido::suites
