// Time per step of an n x n cloth (n = 16, 32, 64, 128, 256) in core's Simulation with each integrator
// and, when the reference adapters are built, in Bullet's deformable world (the exact twin of
// core's symplectic Euler) and Bullet's classic soft body.
//   BM_ClothStep/core-<integrator>/<n>, BM_ClothStep/bullet-deformable/<n>, BM_ClothStep/bullet-classic/<n>
// The cloth: 1 m x 1 m, 1 kg, type B springs 100 N/m and type A 25 N/m, two corner pins, gravity,
// a light air drag c = 0.1 * mean mass /s, and dt half the symplectic-Euler stability limit
// 2 / omega_max, with omega_max^2 bounded by Gershgorin: max over nodes of 2 sum(ks) / m (the
// light free corner decides: dt = 1.0 ms at n = 16, 0.24 ms at n = 64). Same scene for every
// engine (Bullet ignores the drag and reports it). Explicit Euler (and, slowly, midpoint) still
// gains energy on an undamped oscillator; when a run goes unstable it is rebuilt outside the
// timed region and counted in the "restarts" counter. The core runs are labelled with the
// spring-force kernel in use (core/dynamics/packed_springs.h: the widest the CPU supports).
//   BM_SpringForces/<kernel>/<n> times the spring forces alone (PackedSprings::accumulate on the
// same cloth, jiggled) with each kernel the CPU supports, and BM_SpringForces/plain/<n> the plain
// reference loop (accumulate_spring_forces); all give the same bits.
#include "core/dynamics/force_model.h"
#include "core/dynamics/packed_springs.h"
#include "core/scene/cloth_builder.h"
#include "core/simulation/simulation.h"

#include "reference/bullet_deformable.h"
#include "reference/bullet_softbody.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace tecido;

Scene bench_cloth(int n) {
  Scene s;
  s.forces.gravity = Vec3(0, 0, -9.81);
  ClothGridSpec c = unit_square_cloth(n);
  c.origin = Vec3(0, 0, 1);
  c.stiffness_b = 100.0;
  c.stiffness_a = 25.0;
  c.pins = {{0, 0}, {0, n - 1}};
  append_cloth(s, c);
  s.forces.air_drag = 0.1 * 1.0 / (n * n);
  std::vector<double> k_sum(s.particles.size(), 0.0);
  for (const Spring& sp : s.forces.springs) {
    k_sum[sp.i] += sp.stiffness;
    k_sum[sp.j] += sp.stiffness;
  }
  double omega2 = 0.0;
  for (std::size_t i = 0; i < k_sum.size(); ++i) omega2 = std::max(omega2, 2.0 * k_sum[i] * s.particles.inv_mass[i]);
  s.dt = 0.5 * 2.0 / std::sqrt(omega2);
  return s;
}

template <class Engine, class Make>
void run_steps(benchmark::State& state, Make make) {
  const Scene scene = bench_cloth(static_cast<int>(state.range(0)));
  std::unique_ptr<Engine> e = make(scene);
  long long restarts = 0;
  for (auto _ : state) {
    if (!e->step()) {
      state.PauseTiming();
      e = make(scene);
      ++restarts;
      state.ResumeTiming();
    }
  }
  state.counters["restarts"] = static_cast<double>(restarts);
  state.counters["nodes"] = static_cast<double>(scene.particles.size());
  state.counters["springs"] = static_cast<double>(scene.forces.springs.size());
}

// The bench cloth with every particle moved a little (so every spring is stretched) and a velocity.
void jiggled(const Scene& s, std::vector<Vec3>& x, std::vector<Vec3>& v) {
  x = s.particles.x;
  v.assign(x.size(), Vec3::Zero());
  const double h = s.cloth->spacing;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double p = static_cast<double>(i);
    x[i] += 0.1 * h * Vec3(std::sin(1.3 * p), std::cos(0.7 * p), std::sin(2.1 * p));
    v[i] = Vec3(std::cos(p), 0.5, std::sin(0.3 * p));
  }
}

void spring_forces(benchmark::State& state, SpringKernel kernel) {
  const Scene scene = bench_cloth(static_cast<int>(state.range(0)));
  std::vector<Vec3> x, v;
  jiggled(scene, x, v);
  PackedSprings packed(scene.forces.springs);
  packed.set_kernel(kernel);
  for (auto _ : state) {
    packed.accumulate(x, v);
    benchmark::DoNotOptimize(packed.fx());
    benchmark::ClobberMemory();
  }
  state.counters["springs"] = static_cast<double>(scene.forces.springs.size());
}

void plain_spring_forces(benchmark::State& state) {
  const Scene scene = bench_cloth(static_cast<int>(state.range(0)));
  std::vector<Vec3> x, v, f;
  jiggled(scene, x, v);
  for (auto _ : state) {
    accumulate_spring_forces(scene.forces.springs, x, v, f);
    benchmark::DoNotOptimize(f.data());
    benchmark::ClobberMemory();
  }
  state.counters["springs"] = static_cast<double>(scene.forces.springs.size());
}

void core_step(benchmark::State& state, IntegratorKind kind) {
  state.SetLabel(spring_kernel_name(best_spring_kernel()));
  run_steps<Simulation>(state, [kind](const Scene& s) {
    Scene t = s;
    t.integrator = kind;
    return std::make_unique<Simulation>(t);
  });
}

void bullet_deformable_step(benchmark::State& state) {
  run_steps<reference::DeformableTwin>(state, [](const Scene& s) { return std::make_unique<reference::DeformableTwin>(s); });
}

void bullet_classic_step(benchmark::State& state) {
  run_steps<reference::ClassicSoftBody>(state, [](const Scene& s) {
    reference::ClassicSoftBodyOptions o;  // piterations 10, kLST 1, no damping
    return std::make_unique<reference::ClassicSoftBody>(s, o);
  });
}

int register_all() {
  for (IntegratorKind k : {IntegratorKind::Euler, IntegratorKind::Symplectic, IntegratorKind::Midpoint, IntegratorKind::RK4}) {
    const std::string name = std::string("BM_ClothStep/core-") + integrator_name(k);
    benchmark::RegisterBenchmark(name.c_str(), core_step, k)->Arg(16)->Arg(32)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMicrosecond);
  }
  for (SpringKernel k : {SpringKernel::Scalar, SpringKernel::SSE2, SpringKernel::AVX, SpringKernel::AVX512}) {
    if (!spring_kernel_supported(k)) continue;
    const std::string name = std::string("BM_SpringForces/") + spring_kernel_name(k);
    benchmark::RegisterBenchmark(name.c_str(), spring_forces, k)->Arg(64)->Arg(256)->Unit(benchmark::kMicrosecond);
  }
  benchmark::RegisterBenchmark("BM_SpringForces/plain", plain_spring_forces)->Arg(64)->Arg(256)->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("BM_ClothStep/bullet-deformable", bullet_deformable_step)
      ->Arg(16)->Arg(32)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("BM_ClothStep/bullet-classic", bullet_classic_step)
      ->Arg(16)->Arg(32)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMicrosecond);
  return 0;
}

[[maybe_unused]] const int registered = register_all();

}  // namespace
