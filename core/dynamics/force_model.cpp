#include "core/dynamics/force_model.h"

namespace tecido {

void accumulate_spring_forces(const std::vector<Spring>& springs, const std::vector<Vec3>& x,
                              const std::vector<Vec3>& v, std::vector<Vec3>& f) {
  f.assign(x.size(), Vec3::Zero());
  for (const Spring& s : springs) {
    const Vec3 d = x[s.j] - x[s.i];
    const double len = d.norm();
    if (!(len > 0.0)) continue;  // coincident ends: direction undefined, no force (eq. 10)
    const double inv_len = 1.0 / len;
    double mag = s.stiffness * (len - s.rest_length);
    if (s.damping != 0.0) mag += s.damping * (v[s.j] - v[s.i]).dot(d) * inv_len;
    const Vec3 fi = (mag * inv_len) * d;  // mag along u = d / |d|
    f[s.i] += fi;
    f[s.j] -= fi;
  }
}

void compute_accelerations(const ForceModel& model, const std::vector<double>& inv_mass, double t,
                           const std::vector<Vec3>& x, const std::vector<Vec3>& v, std::vector<Vec3>& a) {
  const std::size_t n = x.size();
  if (model.springs.empty()) {
    a.assign(n, Vec3::Zero());
  } else {
    accumulate_spring_forces(model.springs, x, v, a);  // a holds forces until scaled below
  }
  const Vec3 wind = model.wind ? model.wind->at(t) : Vec3::Zero();
  const bool has_wind = model.wind.has_value();
  const double drag = model.air_drag.value_or(0.0);
  const Vec3 g = model.gravity.value_or(Vec3::Zero());
  for (std::size_t i = 0; i < n; ++i) {
    const double w = inv_mass[i];
    if (w == 0.0) {
      a[i].setZero();
      continue;
    }
    Vec3 f = a[i];
    if (has_wind) f += wind;
    if (drag != 0.0) f -= drag * v[i];
    a[i] = w * f + g;
  }
}

double spring_potential_energy(const std::vector<Spring>& springs, const std::vector<Vec3>& x) {
  double e = 0.0;
  for (const Spring& s : springs) {
    const double stretch = (x[s.j] - x[s.i]).norm() - s.rest_length;
    e += 0.5 * s.stiffness * stretch * stretch;
  }
  return e;
}

}  // namespace tecido
