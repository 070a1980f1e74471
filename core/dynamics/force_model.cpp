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

void compute_accelerations(const ForceModel& model, PackedSprings& springs, const std::vector<double>& inv_mass,
                           double t, const std::vector<Vec3>& x, const std::vector<Vec3>& v, std::vector<Vec3>& a) {
  const std::size_t n = x.size();
  a.resize(n);
  const bool has_springs = !springs.empty();
  if (has_springs) springs.accumulate(x, v);
  const double* fx = springs.fx();
  const double* fy = springs.fy();
  const double* fz = springs.fz();
  const Vec3 wind = model.wind ? model.wind->at(t) : Vec3::Zero();
  const bool has_wind = model.wind.has_value();
  const double drag = model.air_drag.value_or(0.0);
  const Vec3 g = model.gravity.value_or(Vec3::Zero());
  // Component-wise, the operations of the overload above in the same order.
  for (std::size_t i = 0; i < n; ++i) {
    const double w = inv_mass[i];
    double* ai = a[i].data();
    if (w == 0.0) {
      ai[0] = ai[1] = ai[2] = 0.0;
      continue;
    }
    double f0 = has_springs ? fx[i] : 0.0, f1 = has_springs ? fy[i] : 0.0, f2 = has_springs ? fz[i] : 0.0;
    if (has_wind) {
      f0 += wind[0];
      f1 += wind[1];
      f2 += wind[2];
    }
    if (drag != 0.0) {
      const double* vi = v[i].data();
      f0 -= drag * vi[0];
      f1 -= drag * vi[1];
      f2 -= drag * vi[2];
    }
    ai[0] = w * f0 + g[0];
    ai[1] = w * f1 + g[1];
    ai[2] = w * f2 + g[2];
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
