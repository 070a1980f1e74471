#include "comparisons/suites/drift/invariants.h"

#include "comparisons/suites/drift/theory.h"
#include "comparisons/suites/sweep.h"
#include "core/dynamics/force_model.h"
#include "core/simulation/simulation.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace tecido::suites::drift {

double energy(const Scene& scene, const std::vector<Vec3>& x, const std::vector<Vec3>& v) {
  double e = spring_potential_energy(scene.forces.springs, x);
  for (std::size_t i = 0; i < x.size(); ++i)
    if (scene.particles.inv_mass[i] > 0) e += 0.5 * v[i].squaredNorm() / scene.particles.inv_mass[i];
  return e;
}

Vec3 momentum(const std::vector<double>& inv_mass, const std::vector<Vec3>& v) {
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i < v.size(); ++i)
    if (inv_mass[i] > 0) p += v[i] / inv_mass[i];
  return p;
}

Vec3 angular_momentum(const std::vector<double>& inv_mass, const std::vector<Vec3>& x, const std::vector<Vec3>& v) {
  Vec3 l = Vec3::Zero();
  for (std::size_t i = 0; i < v.size(); ++i)
    if (inv_mass[i] > 0) l += x[i].cross(v[i] / inv_mass[i]);
  return l;
}

double momentum_scale(const std::vector<double>& inv_mass, const std::vector<Vec3>& v) {
  double s = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (inv_mass[i] > 0) s += v[i].norm() / inv_mass[i];
  return s;
}

double angular_momentum_scale(const std::vector<double>& inv_mass, const std::vector<Vec3>& x,
                              const std::vector<Vec3>& v) {
  double s = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (inv_mass[i] > 0) s += x[i].norm() * v[i].norm() / inv_mass[i];
  return s;
}

InvariantTally::InvariantTally(const Scene& s, long long steps_) : scene(s), steps(steps_) {
  const auto& p = s.particles;
  e0 = energy(s, p.x, p.v);
  p0 = momentum(p.inv_mass, p.v);
  l0 = angular_momentum(p.inv_mass, p.x, p.v);
  p_scale0 = momentum_scale(p.inv_mass, p.v);
  l_scale0 = angular_momentum_scale(p.inv_mass, p.x, p.v);
  r.steps = steps_;
}

void InvariantTally::sample(long long i, double t, const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                            const Vec3& dl_theory, bool plot) {
  const std::vector<double>& w = scene.particles.inv_mass;
  const double erel = std::abs(energy(scene, x, v) - e0) / e0;
  r.final_rel_energy = erel;
  double& half = i <= steps / 2 ? first_half : second_half;
  half = std::max(half, erel);
  r.momentum_error = std::max(r.momentum_error, (momentum(w, v) - p0).norm() / std::max(p_scale0, momentum_scale(w, v)));
  const double l_scale = std::max(l_scale0, angular_momentum_scale(w, x, v));
  const Vec3 dl = angular_momentum(w, x, v) - l0;
  r.angular_momentum_error = std::max(r.angular_momentum_error, dl.norm() / l_scale);
  r.angular_momentum_vs_theory = std::max(r.angular_momentum_vs_theory, (dl - dl_theory).norm() / l_scale);
  st += t, se += erel, stt += t * t, ste += t * erel, ++n;
  if (plot) r.energy_curve.push_back({t, erel});
}

InvariantRun InvariantTally::finish() {
  r.max_rel_energy = std::max(first_half, second_half);
  r.growth_rate = n > 1 ? (n * ste - st * se) / (n * stt - st * st) : std::nan("");
  r.last_over_first_half = second_half / std::max(first_half, 1e-300);
  return r;
}

InvariantRun run_invariants(const Scene& scene, IntegratorKind kind, const Settings& s) {
  Scene sc = scene;
  sc.integrator = kind;
  Simulation sim(sc);
  InvariantTally tally(sc, s.steps);
  const std::optional<Tableau> tableau = runge_kutta_tableau(kind);
  Vec3 dl_theory = Vec3::Zero();
  for (long long i = 1; i <= s.steps; ++i) {
    const Particles& p = sim.particles();
    if (tableau) dl_theory += angular_momentum_change(*tableau, sc.forces.springs, p.inv_mass, p.x, p.v, sc.dt);
    if (!sim.step()) {
      tally.r.unstable_at_step = sim.instability() ? sim.instability()->step : i;
      break;
    }
    if (i % s.sample_every == 0) tally.sample(i, sim.time(), sim.particles().x, sim.particles().v, dl_theory, i % s.plot_every == 0);
  }
  return tally.finish();
}

io::Json invariant_json(const InvariantRun& r) {
  io::Json curve = io::Json::array();
  for (const auto& c : r.energy_curve) curve.push_back({num(c[0]), num(c[1])});
  return {{"steps", r.steps},
          {"unstable_at_step", r.unstable_at_step},
          {"final_rel_energy", num(r.final_rel_energy)},
          {"max_rel_energy", num(r.max_rel_energy)},
          {"growth_rate", num(r.growth_rate)},
          {"last_over_first_half", num(r.last_over_first_half)},
          {"momentum_error", num(r.momentum_error)},
          {"angular_momentum_error", num(r.angular_momentum_error)},
          {"angular_momentum_vs_theory", num(r.angular_momentum_vs_theory)},
          {"energy_curve", curve}};
}

InvariantRun invariant_from_json(const io::Json& j) {
  InvariantRun r;
  r.steps = j.at("steps").get<long long>();
  r.unstable_at_step = j.at("unstable_at_step").get<long long>();
  r.final_rel_energy = get_num(j.at("final_rel_energy"));
  r.max_rel_energy = get_num(j.at("max_rel_energy"));
  r.growth_rate = get_num(j.at("growth_rate"));
  r.last_over_first_half = get_num(j.at("last_over_first_half"));
  r.momentum_error = get_num(j.at("momentum_error"));
  r.angular_momentum_error = get_num(j.at("angular_momentum_error"));
  r.angular_momentum_vs_theory = get_num(j.at("angular_momentum_vs_theory"));
  for (const io::Json& c : j.at("energy_curve")) r.energy_curve.push_back({get_num(c.at(0)), get_num(c.at(1))});
  return r;
}

}  // namespace tecido::suites::drift
