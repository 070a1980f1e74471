#include "comparisons/suites/drift/bullet_cases.h"

#include "comparisons/suites/drift/scenes.h"
#include "comparisons/suites/drift/theory.h"
#include "comparisons/suites/sweep.h"
#include "core/simulation/simulation.h"
#include "reference/bullet_deformable.h"
#include "reference/bullet_softbody.h"
#include "reference/klst_calibration.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tecido::suites::drift {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double rms_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b, double* max_out) {
  double s = 0.0, m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double d = (a[i] - b[i]).norm();
    s += d * d;
    m = std::max(m, d);
  }
  *max_out = m;
  return std::sqrt(s / static_cast<double>(a.size()));
}

io::Json unstable_json(long long step, const char* engine) { return {{"step", step}, {"engine", engine}}; }

/// Steps core and the twin together to step i; false (and `unstable` set) when either fails.
bool step_both(Simulation& core, reference::DeformableTwin& twin, long long i, io::Json& unstable) {
  if (!core.step()) {
    unstable = unstable_json(i, "core");
    return false;
  }
  if (!twin.step()) {
    unstable = unstable_json(i, "Bullet");
    return false;
  }
  return true;
}

}  // namespace

io::Json twin_case(const Settings& s) {
  const Scene scene = twin_cloth(s, Vec3::Zero(), true);
  Simulation core(scene);
  reference::DeformableTwin twin(scene);
  io::Json unstable = nullptr, curve = io::Json::array();
  double rms_window = 0.0;
  std::vector<double> crossing(std::size(s.twin_thresholds), kNaN);
  const long long steps = std::llround(s.twin_seconds / s.twin_dt);
  for (long long i = 1; i <= steps && step_both(core, twin, i, unstable); ++i) {
    double mx = 0.0;
    const double r = rms_distance(core.particles().x, twin.positions(), &mx), t = core.time();
    if (t <= s.twin_window + 1e-9) rms_window = std::max(rms_window, r);
    for (std::size_t k = 0; k < crossing.size(); ++k)
      if (std::isnan(crossing[k]) && r > s.twin_thresholds[k]) crossing[k] = t;
    curve.push_back({num(t), num(r), num(mx)});
  }
  io::Json jc = io::Json::array();
  for (double c : crossing) jc.push_back(num(c));
  return {{"unstable", unstable}, {"rms_window", num(rms_window)}, {"crossings", jc},
          {"curve", curve},       {"not_modelled", twin.not_modelled()}};
}

io::Json falling_case(const Settings& s) {
  const Scene scene = falling_cloth(s);
  Simulation core(scene);
  core.set_log_contacts(true);
  reference::DeformableTwin twin(scene);
  const double margin = twin.plane_contact_offset();
  io::Json unstable = nullptr;
  double t_twin = kNaN;
  const long long steps = std::llround(s.fall_seconds / s.twin_dt);
  for (long long i = 1; i <= steps && step_both(core, twin, i, unstable); ++i) {
    if (!std::isnan(t_twin)) continue;
    double zmin = std::numeric_limits<double>::infinity();
    for (const Vec3& x : twin.positions()) zmin = std::min(zmin, x.z());
    if (zmin <= margin + 1e-6) t_twin = twin.time();
  }
  double z_core = 0.0, z_twin = 0.0;
  for (const Vec3& x : core.particles().x) z_core = std::max(z_core, std::abs(x.z()));
  for (const Vec3& x : twin.positions()) z_twin = std::max(z_twin, x.z());
  const double g = -scene.forces.gravity->z();
  return {{"unstable", unstable},
          {"t_exact", num(fall_time(s.fall_height, g))},
          {"t_core", num(core.contact_log().empty() ? kNaN : core.contact_log().front().time)},
          {"t_twin", num(t_twin)},
          {"margin", num(margin)},
          {"t_exact_margin", num(fall_time(s.fall_height - margin, g))},
          {"z_core", num(z_core)},
          {"z_twin", num(z_twin)}};
}

namespace {

reference::SagCalibrationOptions calibration_options(const Settings& s) {
  reference::SagCalibrationOptions o;
  o.piterations = s.classic_piterations;
  o.kdp = s.classic_kdp;
  o.rest_speed = s.classic_rest_speed;
  o.max_time = s.classic_max_time;
  o.relative_tolerance = s.classic_calibration_tolerance;
  return o;
}

io::Json calibration_json(const reference::SagCalibration& c) {
  return {{"klst", num(c.klst)},           {"core_sag", num(c.core_sag)},
          {"bullet_sag", num(c.bullet_sag)}, {"relative_error", num(c.relative_error)},
          {"evaluations", c.evaluations},  {"sag_at_klst_1", num(c.sag_at_klst_1)},
          {"shape_rms", num(c.shape_rms)}, {"shape_max", num(c.shape_max)},
          {"bracketed", c.bracketed}};
}

/// Largest node distance between two shapes [m] (0 when bit-identical).
double max_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double m = 0.0;
  rms_distance(a, b, &m);
  return m;
}

}  // namespace

io::Json classic_case(const Settings& s) {
  const Scene curtain = classic_curtain(s);
  const reference::SagCalibrationOptions o = calibration_options(s);
  reference::SagCalibration cal;
  const double klst = reference::calibrate_klst_for_sag(curtain, o, &cal);
  const Scene loaded = with_load(curtain, s.classic_load_factor);
  const auto xb_cal = reference::settle_classic(curtain, klst, o).x;
  const auto xc = reference::settle_core(loaded, o).x, xb = reference::settle_classic(loaded, klst, o).x;
  const double sag_c = reference::mean_sag(loaded, xc), sag_b = reference::mean_sag(loaded, xb);
  double shape_max = 0.0;
  const double shape_rms = rms_distance(xc, xb, &shape_max);
  reference::ClassicSoftBodyOptions co;
  co.klst = klst;
  co.piterations = o.piterations;
  co.kdp = o.kdp;
  const io::Json load = {{"factor", num(s.classic_load_factor)}, {"core_sag", num(sag_c)},
                         {"bullet_sag", num(sag_b)},             {"sag_ratio", num(sag_b / sag_c)},
                         {"shape_rms", num(shape_rms)},          {"shape_max", num(shape_max)},
                         {"bullet_shape_change", num(max_distance(xb, xb_cal))}};
  return {{"calibration", calibration_json(cal)},
          {"load", load},
          {"not_modelled", reference::ClassicSoftBody(loaded, co).not_modelled()}};
}

io::Json wind_case(const Settings&) {
  const Scene s = windy_cloth();
  return {{"twin", reference::DeformableTwin(s).not_modelled()},
          {"classic", reference::ClassicSoftBody(s).not_modelled()}};
}

}  // namespace tecido::suites::drift
