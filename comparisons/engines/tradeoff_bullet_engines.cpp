#include "comparisons/engines/tradeoff_bullet_engines.h"

// Everything here needs the Bullet adapters, which exist only in the reference build.
#ifdef TECIDO_HAVE_REFERENCE

#include "reference/bullet_deformable.h"
#include "reference/bullet_softbody.h"
#include "reference/klst_calibration.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <future>
#include <map>
#include <mutex>
#include <stdexcept>
#include <tuple>

namespace tecido::suites {

namespace {

// How far the Bullet engines are run in the suite's sweep: cloths of at most kMaxSide^2 nodes
// (the implicit deformable world, whose Newton and CG iterations cost most: kMaxSideImplicit^2)
// and only the kMaxSteps largest swept steps (h0, h0/2, h0/4). Measured in Release on the 2-core
// machine: per run of 1 s at h0 = 2^-7 s on the 16^2 cloth (1770 springs) core's symplectic Euler
// takes 0.7 ms, the deformable twin 22 ms, the implicit world 33-85 ms (1-16 CG iterations), the
// classic body 16-47 ms (1-16 sweeps) plus its kLST calibration (2-4 settles of a few simulated
// seconds); every Bullet cost grows as nodes x steps (at 32^2: 8x), so the full sweep (up to
// 128^2 and h0/16) would take hours. The engines carry this range (TradeoffEngine::max_n, max_steps), so the suite skips the
// points outside; run() itself also returns nothing there at once, for other callers.
constexpr int kMaxSide = 32;
constexpr int kMaxSideImplicit = 16;
constexpr int kMaxSideClassic = 16;
constexpr int kMaxSteps = 3;

/// True when (scene, h) lies in the range described above: the scene's side (sqrt of the node
/// count) is at most max_side and h is no smaller than the suite's h0 / 2^(kMaxSteps - 1), h0 being
/// the suite's first step, 2^ceil(log2(2 / omega_bound)).
bool covered(const Scene& scene, double h, int max_side) {
  const double side = std::sqrt(static_cast<double>(scene.particles.size()));
  if (side > max_side + 1e-9) return false;
  const double wb = omega_bound(scene);
  if (!(wb > 0.0)) return true;
  const double h0 = std::pow(2.0, std::ceil(std::log2(2.0 / wb)));
  return h >= h0 / std::pow(2.0, kMaxSteps - 1) * (1.0 - 1e-12);
}

/// FNV-1a over the bytes of everything the calibration reads from the scene.
class Fingerprint {
 public:
  void add(const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h_ = (h_ ^ b[i]) * 1099511628211ull;
  }
  void add(double x) { add(&x, sizeof x); }
  void add(const Vec3& v) {
    for (int k = 0; k < 3; ++k) add(v[k]);
  }
  std::uint64_t value() const { return h_; }

 private:
  std::uint64_t h_ = 1469598103934665603ull;
};

std::uint64_t fingerprint(const Scene& s) {
  Fingerprint f;
  const auto& p = s.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    f.add(p.x[i]);
    f.add(p.v[i]);
    f.add(p.inv_mass[i]);
  }
  for (const Spring& sp : s.forces.springs) {
    f.add(&sp.i, sizeof sp.i);
    f.add(&sp.j, sizeof sp.j);
    f.add(sp.stiffness);
    f.add(sp.rest_length);
    f.add(sp.damping);
  }
  f.add(s.forces.gravity.value_or(Vec3::Zero()));
  return f.value();
}

/// First estimate of kLST for calibrate_klst_for_sag's secant. One sweep of Bullet's link
/// projection removes the fraction kLST of a link's stretch; a Hooke spring of stiffness k between
/// nodes of inverse masses w_i, w_j removes about h^2 k (w_i + w_j) of it in one symplectic step.
/// Equating the two over `piterations` sweeps, -ln(1 - kLST) piterations = c h^2 k_max (2 w), with
/// w the median free inverse mass and c = 0.8 fitted on the 16^2 curtain (calibrated kLST 0.20,
/// 0.053, 0.0136 at 1, 4, 16 sweeps; h0 / 2 and h0 / 4 follow the h^2 law within 3 %).
double klst_guess(const Scene& scene, double h, int piterations) {
  std::vector<double> w;
  for (double wi : scene.particles.inv_mass)
    if (wi > 0.0) w.push_back(wi);
  double k_max = 0.0;
  for (const Spring& sp : scene.forces.springs) k_max = std::max(k_max, sp.stiffness);
  if (w.empty() || !(k_max > 0.0)) return 1.0;
  std::nth_element(w.begin(), w.begin() + static_cast<std::ptrdiff_t>(w.size() / 2), w.end());
  const double x = 0.8 * h * h * k_max * 2.0 * w[w.size() / 2] / piterations;
  return std::clamp(1.0 - std::exp(-x), 1e-4, 1.0);
}

}  // namespace

double classic_klst(const Scene& scene, double h, int piterations) {
  using Key = std::tuple<std::uint64_t, std::size_t, double, int>;
  static std::mutex mutex;
  static std::map<Key, std::shared_future<double>> cache;
  const Key key{fingerprint(scene), scene.particles.size(), h, piterations};
  std::promise<double> promise;
  std::shared_future<double> value;
  bool mine = false;
  {
    std::lock_guard<std::mutex> lock(mutex);
    auto it = cache.find(key);
    if (it == cache.end()) {
      value = promise.get_future().share();
      cache.emplace(key, value);
      mine = true;
    } else {
      value = it->second;
    }
  }
  if (mine) {
    // Outside the lock: other keys calibrate in parallel; callers of this key wait on `value`.
    try {
      Scene s = scene;
      s.dt = h;
      s.integrator = IntegratorKind::Symplectic;
      reference::SagCalibrationOptions o;
      o.piterations = piterations;
      // Settling damping with the same rate, 6.4 /s (kDP 0.05 at h = 2^-7 s), at every step; the
      // settled shape does not depend on it. A 1 % sag match (2.5 mm on the 16^2 curtain's
      // 0.25 m) is far inside the classic body's dynamic mismatch (about 5 cm RMS at t = 1 s).
      o.kdp = std::min(0.5, 6.4 * h);
      o.rest_speed = 1e-4;
      o.relative_tolerance = 1e-2;
      o.max_time = 30.0;
      o.klst_guess = klst_guess(s, h, piterations);
      promise.set_value(reference::calibrate_klst_for_sag(s, o));
    } catch (...) {
      promise.set_exception(std::current_exception());
    }
  }
  return value.get();
}

TradeoffEngine bullet_deformable_tradeoff_engine() {
  TradeoffEngine e;
  e.name = "bullet-deformable";
  e.evaluations_per_step = 1.0;  // one spring-force evaluation per symplectic step
  e.max_n = kMaxSide;
  e.max_steps = kMaxSteps;
  e.run = [](const Scene& scene, double h, double seconds) -> std::optional<std::vector<Vec3>> {
    if (!covered(scene, h, kMaxSide)) return std::nullopt;
    return reference::run_deformable_twin(scene, h, seconds).x;
  };
  return e;
}

TradeoffEngine bullet_deformable_implicit_tradeoff_engine(int cg_iterations) {
  if (cg_iterations < 1) throw std::invalid_argument("bullet_deformable_implicit_tradeoff_engine: cg_iterations >= 1");
  TradeoffEngine e;
  e.name = "bullet-deformable-implicit-it" + std::to_string(cg_iterations);
  e.evaluations_per_step = 0.0;  // Newton x CG products of the force Jacobian: varies, not counted
  e.max_n = kMaxSideImplicit;
  e.max_steps = kMaxSteps;
  e.run = [cg_iterations](const Scene& scene, double h, double seconds) -> std::optional<std::vector<Vec3>> {
    if (!covered(scene, h, kMaxSideImplicit)) return std::nullopt;
    reference::DeformableTwinOptions o;
    o.implicit = true;
    o.krylov_iterations = cg_iterations;
    return reference::run_deformable_twin(scene, h, seconds, o).x;
  };
  return e;
}

TradeoffEngine bullet_classic_tradeoff_engine(int piterations) {
  if (piterations < 1) throw std::invalid_argument("bullet_classic_tradeoff_engine: piterations >= 1");
  TradeoffEngine e;
  e.name = "bullet-classic-it" + std::to_string(piterations);
  e.evaluations_per_step = 0.0;  // position-based: no force evaluations
  e.max_n = kMaxSideClassic;
  e.max_steps = kMaxSteps;
  e.run = [piterations](const Scene& scene, double h, double seconds) -> std::optional<std::vector<Vec3>> {
    if (!covered(scene, h, kMaxSideClassic)) return std::nullopt;
    double klst = 1.0;
    try {
      klst = classic_klst(scene, h, piterations);
    } catch (const std::exception&) {
      return std::nullopt;  // core or Bullet went unstable while settling: no calibrated body
    }
    reference::ClassicSoftBodyOptions o;
    o.klst = klst;
    o.piterations = piterations;
    o.kdp = 0.0;  // the scene is undamped
    return reference::run_classic_soft_body(scene, h, seconds, o).x;
  };
  return e;
}

std::vector<TradeoffEngine> bullet_tradeoff_engines() {
  std::vector<TradeoffEngine> engines;
  engines.push_back(bullet_deformable_tradeoff_engine());
  for (int k : {1, 4, 16}) engines.push_back(bullet_deformable_implicit_tradeoff_engine(k));
  for (int k : {1, 4, 16}) engines.push_back(bullet_classic_tradeoff_engine(k));
  return engines;
}

}  // namespace tecido::suites

#endif  // TECIDO_HAVE_REFERENCE
