#include "comparisons/engines/classic_klst.h"

#include "reference/klst_calibration.h"

#include <algorithm>
#include <cstdint>
#include <future>
#include <map>
#include <mutex>
#include <tuple>

namespace tecido::engines {

namespace {

/// FNV-1a over the bytes of everything the calibration reads.
class KlstFingerprint {
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

std::uint64_t klst_fingerprint(const Scene& s, const ClassicCalibration& c) {
  KlstFingerprint f;
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
  for (double x : {c.kdp_rate, c.rest_speed, c.relative_tolerance, c.max_time}) f.add(x);
  return f.value();
}

double calibrate_klst(const Scene& scene, double h, int piterations, const ClassicCalibration& c) {
  Scene s = scene;
  s.dt = h;
  s.integrator = IntegratorKind::Symplectic;
  reference::SagCalibrationOptions o;
  o.piterations = piterations;
  o.kdp = std::min(0.5, c.kdp_rate * h);  // the same settling rate at every step; the shape does not depend on it
  o.rest_speed = c.rest_speed;
  o.relative_tolerance = c.relative_tolerance;
  o.max_time = c.max_time;
  o.klst_guess = reference::klst_scaling_guess(s, h, piterations);
  return reference::calibrate_klst_for_sag(s, o);
}

}  // namespace

double classic_klst(const Scene& scene, double h, int piterations, const ClassicCalibration& c) {
  using Key = std::tuple<std::uint64_t, std::size_t, double, int>;
  static std::mutex mutex;
  static std::map<Key, std::shared_future<double>> cache;
  const Key key{klst_fingerprint(scene, c), scene.particles.size(), h, piterations};
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
      promise.set_value(calibrate_klst(scene, h, piterations, c));
    } catch (...) {
      promise.set_exception(std::current_exception());
    }
  }
  return value.get();
}

}  // namespace tecido::engines
