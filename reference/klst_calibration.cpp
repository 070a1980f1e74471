#include "reference/klst_calibration.h"

#include "core/simulation/simulation.h"
#include "reference/bullet_softbody.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace tecido::reference {

double mean_sag(const Scene& scene, const std::vector<Vec3>& x) {
  if (!scene.forces.gravity || !(scene.forces.gravity->norm() > 0.0))
    throw std::invalid_argument("mean_sag: the scene has no gravity");
  const auto& p = scene.particles;
  if (x.size() != p.size()) throw std::invalid_argument("mean_sag: positions do not match the scene's particles");
  const Vec3 down = scene.forces.gravity->normalized();
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.pinned[i] || p.inv_mass[i] == 0.0) continue;
    sum += (x[i] - p.x[i]).dot(down);
    ++n;
  }
  if (n == 0) throw std::invalid_argument("mean_sag: the scene has no free particle");
  return sum / static_cast<double>(n);
}

namespace {

std::string short_number(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

double max_speed(const std::vector<Vec3>& v) {
  double m = 0.0;
  for (const Vec3& vi : v) m = std::max(m, vi.norm());
  return m;
}

/// 10 /s times the mean mass of the free particles [kg/s].
double default_settling_drag(const Scene& s) {
  double m = 0.0;
  std::size_t n = 0;
  for (double w : s.particles.inv_mass) {
    if (w > 0.0) {
      m += 1.0 / w;
      ++n;
    }
  }
  return 10.0 * m / static_cast<double>(std::max<std::size_t>(n, 1));
}

/// Steps `engine` (core's, or a Bullet body: step, velocities, positions, time, steps_done) until
/// every node is slower than `rest_speed` [m/s] or `max_time` [s] has been simulated. Throws
/// std::runtime_error naming `who` when a step reports a non-finite state.
template <class Engine>
Settled settle(Engine& engine, double rest_speed, double max_time, const char* who) {
  Settled r;
  while (engine.time() < max_time) {
    if (!engine.step())
      throw std::runtime_error(std::string(who) + " went unstable while settling, at step " +
                               std::to_string(engine.steps_done() + 1));
    if (max_speed(engine.velocities()) < rest_speed) {
      r.settled = true;
      break;
    }
  }
  r.x = engine.positions();
  return r;
}

/// Core's Simulation with the stepping calls settle() makes.
struct SettlingCore {
  explicit SettlingCore(const Scene& scene) : sim(scene) {}
  bool step() { return sim.step(); }
  std::vector<Vec3> positions() const { return sim.particles().x; }
  std::vector<Vec3> velocities() const { return sim.particles().v; }
  double time() const { return sim.time(); }
  long long steps_done() const { return sim.steps_done(); }
  Simulation sim;
};

}  // namespace

Settled settle_core(const Scene& scene, const SagCalibrationOptions& o) {
  Scene s = scene;
  s.integrator = IntegratorKind::Symplectic;  // the equilibrium does not depend on the integrator
  if (!s.forces.air_drag || *s.forces.air_drag == 0.0)
    s.forces.air_drag = o.core_air_drag > 0.0 ? o.core_air_drag : default_settling_drag(s);
  SettlingCore core(s);
  return settle(core, o.rest_speed, o.max_time, "core");
}

Settled settle_classic(const Scene& scene, double klst, const SagCalibrationOptions& o) {
  ClassicSoftBodyOptions co;
  co.klst = klst;
  co.piterations = o.piterations;
  co.kdp = o.kdp;
  ClassicSoftBody body(scene, co);
  return settle(body, o.rest_speed, o.max_time, ("Bullet (kLST = " + short_number(klst) + ")").c_str());
}

namespace {

struct Trial {
  double klst = 1.0, sag = 0.0;
  bool settled = false;
  std::vector<Vec3> x;
};

/// The trials of one calibration: runs Bullet at a kLST and keeps the trial nearest core's sag.
struct Search {
  const Scene& scene;
  const SagCalibrationOptions& o;
  double target = 0.0;  ///< core's sag [m]
  double tol = 0.0;     ///< accepted |sag - target| [m]
  int evaluations = 0;
  Trial best;

  Trial run(double klst) {
    Settled s = settle_classic(scene, klst, o);
    ++evaluations;
    Trial t{klst, mean_sag(scene, s.x), s.settled, std::move(s.x)};
    if (evaluations == 1 || std::abs(t.sag - target) < std::abs(best.sag - target)) best = t;
    return t;
  }
  bool matched() const { return evaluations > 0 && std::abs(best.sag - target) <= tol; }
};

/// Safeguarded secant on f(u) = log(sag(e^u) / target), u = log kLST in [log klst_min, 0], from
/// the guess. f falls as u grows; the first secant slope is -1 (sag ~ 1/kLST). A bracket
/// [soft, stiff] (f >= 0 at soft, f <= 0 at stiff) is kept once both signs are seen, and a secant
/// step that leaves it is replaced by the bracket's midpoint. Returns whether it bracketed or matched.
bool secant_search(Search& s) {
  if (!(s.target > 0.0)) throw std::runtime_error("calibrate_klst_for_sag: core's sag is not positive; no kLST guess can match it");
  const double u_min = std::log(s.o.klst_min), log_target = std::log(s.target);
  auto f = [&](const Trial& t) { return std::log(t.sag) - log_target; };
  double soft = u_min, stiff = 0.0;
  bool have_soft = false, have_stiff = false;
  auto bracket = [&](double u, double fu) {
    if (fu >= 0.0 && (!have_soft || u > soft)) soft = u, have_soft = true;
    if (fu <= 0.0 && (!have_stiff || u < stiff)) stiff = u, have_stiff = true;
  };
  double u0 = std::clamp(std::log(s.o.klst_guess), u_min, 0.0);
  const Trial t0 = s.run(std::exp(u0));
  if (!(t0.sag > 0.0)) throw std::runtime_error("calibrate_klst_for_sag: Bullet's sag is not positive at the kLST guess");
  double f0 = f(t0);
  bracket(u0, f0);
  double u1 = std::clamp(u0 + f0, u_min, 0.0);  // slope -1
  for (int it = 0; it < s.o.max_bisections && !s.matched() && u1 != u0; ++it) {
    const Trial t1 = s.run(std::exp(u1));
    if (!(t1.sag > 0.0)) break;
    const double f1 = f(t1);
    bracket(u1, f1);
    const double slope = (f1 - f0) / (u1 - u0);
    double u2 = slope < 0.0 && std::isfinite(slope) ? u1 - f1 / slope : 0.5 * (soft + stiff);
    if (have_soft && have_stiff && !(u2 > soft && u2 < stiff)) u2 = 0.5 * (soft + stiff);
    u0 = u1;
    f0 = f1;
    u1 = std::clamp(u2, u_min, 0.0);
  }
  return s.matched() || (have_soft && have_stiff);
}

/// Bisection in log kLST on [klst_min, 1], after trying kLST = 1 (filled into *sag_at_1). Returns
/// whether core's sag lies within what Bullet reaches.
bool bisection_search(Search& s, double* sag_at_1) {
  const Trial stiff = s.run(1.0);
  *sag_at_1 = stiff.sag;
  if (stiff.sag > s.target + s.tol) return false;  // even kLST = 1 sags more than core
  if (s.matched()) return true;
  const Trial soft = s.run(s.o.klst_min);
  if (soft.sag < s.target - s.tol) return false;  // even klst_min is stiffer than core
  double lo = std::log(s.o.klst_min), hi = 0.0;   // sag(lo) >= target >= sag(hi)
  for (int it = 0; it < s.o.max_bisections && !s.matched(); ++it) {
    const double mid = 0.5 * (lo + hi);
    (s.run(std::exp(mid)).sag > s.target ? lo : hi) = mid;  // too soft: stiffer
  }
  return true;
}

/// RMS and largest node distance between two settled shapes.
void compare_shapes(const std::vector<Vec3>& a, const std::vector<Vec3>& b, SagCalibration& cal) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double d = (a[i] - b[i]).norm();
    sum += d * d;
    cal.shape_max = std::max(cal.shape_max, d);
  }
  cal.shape_rms = a.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(a.size()));
}

}  // namespace

double calibrate_klst_for_sag(const Scene& scene, const SagCalibrationOptions& o, SagCalibration* result) {
  if (!(o.klst_min > 0.0 && o.klst_min < 1.0)) throw std::invalid_argument("calibrate_klst_for_sag: klst_min must be in (0, 1)");
  SagCalibration cal;
  cal.piterations = o.piterations;
  cal.kdp = o.kdp;
  cal.dt = scene.dt;
  const Settled core = settle_core(scene, o);
  cal.core_settled = core.settled;
  cal.core_sag = mean_sag(scene, core.x);
  Search search{scene, o, cal.core_sag, o.relative_tolerance * std::abs(cal.core_sag), 0, {}};
  if (o.klst_guess > 0.0) {
    cal.bracketed = secant_search(search);
    cal.sag_at_klst_1 = std::nan("");
  } else {
    cal.bracketed = bisection_search(search, &cal.sag_at_klst_1);
  }
  const Trial& best = search.best;
  cal.evaluations = search.evaluations;
  cal.klst = best.klst;
  cal.bullet_sag = best.sag;
  cal.bullet_settled = best.settled;
  cal.sag_error = best.sag - cal.core_sag;
  cal.relative_error = cal.core_sag != 0.0 ? std::abs(cal.sag_error) / std::abs(cal.core_sag) : std::abs(cal.sag_error);
  compare_shapes(best.x, core.x, cal);
  if (result) *result = cal;
  return cal.klst;
}

double klst_scaling_guess(const Scene& scene, double h, int piterations) {
  std::vector<double> w;
  for (double wi : scene.particles.inv_mass)
    if (wi > 0.0) w.push_back(wi);
  double k_max = 0.0;
  for (const Spring& sp : scene.forces.springs) k_max = std::max(k_max, sp.stiffness);
  if (w.empty() || !(k_max > 0.0) || piterations < 1) return 1.0;
  std::nth_element(w.begin(), w.begin() + static_cast<std::ptrdiff_t>(w.size() / 2), w.end());
  const double x = 0.8 * h * h * k_max * 2.0 * w[w.size() / 2] / piterations;
  return std::clamp(1.0 - std::exp(-x), 1e-4, 1.0);
}

}  // namespace tecido::reference
