// Continuous self-collision of an n x n cloth over one step, next to discrete self-collision of
// one frame of the same step (the ratio is the cost of looking between the frames).
//
// The step: a side of 1 m folded over itself along x = 0.5 (a half-turn bend of radius H / 2,
// the flap's flat part at height H), with a ripple of amplitude 0.03 m (sin 9u sin 7v) on both
// layers, so the layers cross along curves. Between the two frames the fold closes from
// H = 0.04 m to H = 0.02 m (the flap comes down 2 cm, 2.5 edge lengths at n = 128, 5 at 256)
// while the whole cloth falls by 1 cm: a fast fold, 1.2 m/s, and a fall at 0.6 m/s over one
// 60 Hz step; the layers pass through each other over a wide band (about 22k touching pairs at
// n = 128). The second frame is bench_self_collision.cpp's folded frame. The "gentle" step
// closes the fold from H = 0.0225 m and drops 2 mm (0.15 m/s and 0.12 m/s at 60 Hz).
//   BM_ContinuousSelfCollision/core/<n>             detect(frame 0, frame 1): core/cloth/
//                                                   continuous_self_collision.h
//   BM_ContinuousSelfCollision/discrete/<n>         discrete self-collision of frame 1
//                                                   (self_collision.h)
//   BM_ContinuousSelfCollision/core-gentle/<n>, .../discrete-gentle/<n>  the same, gentle step
//   BM_ContinuousSelfCollision/confirmed/<n>        detect, then each candidate confirmed by the
//                                                   exact referee (reference::exact_ccd_hit): the
//                                                   exact answer, what `tecido selfcollide --to`
//                                                   computes (engine core)
//   BM_ContinuousSelfCollision/threads:<t>/<n>      detect on t threads (wall time: UseRealTime)
//   BM_ContinuousSelfCollision/discrete-threads:<t>/<n>  discrete detection on t threads (wall time)
// Both trees are built once on the rest shape, outside the timed loop. Counters: `pairs`
// (reported pairs), `tests` (primitive pairs handed to the continuous test), `tree_pairs`
// (triangle pairs sharing no vertex from the swept-box tree).
#include "core/cloth/continuous_self_collision.h"
#include "core/cloth/self_collision.h"
#include "core/scene/cloth_builder.h"
#include "reference/exact_ccd.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <string>

namespace {

using namespace tecido;

struct Step {
  std::vector<Vec3> rest, x0, x1;
  std::vector<std::array<int, 3>> tris;
};

/// The frames of the fast (0) and gentle (1) steps: flap heights H0 -> 0.02 m, drop.
constexpr double kStartHeight[2] = {0.04, 0.0225}, kDrop[2] = {0.01, 0.002};

/// The folded cloth with flap height h, lowered by `drop`.
std::vector<Vec3> folded(const std::vector<Vec3>& rest, double h, double drop) {
  std::vector<Vec3> x = rest;
  const double r = 0.5 * h;
  for (Vec3& p : x) {
    const double u = p.x(), v = p.y();
    const double ripple = 0.03 * std::sin(9.0 * u + 1.0) * std::sin(7.0 * v);
    if (u <= 0.5) {
      p = Vec3(u, v, ripple - drop);
    } else {
      const double a = (u - 0.5) / r;
      if (a < M_PI) {
        p = Vec3(0.5 + r * std::sin(a), v, r - r * std::cos(a) + ripple - drop);
      } else {
        p = Vec3(0.5 - (u - 0.5 - M_PI * r), v, h - ripple - drop);
      }
    }
  }
  return x;
}

const Step& step_of(int n, int kind) {
  static std::map<int, Step> cache;
  const int key = 2 * n + kind;
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  Scene s;
  ClothGridSpec spec;
  spec.rows = spec.cols = n;
  spec.spacing = 1.0 / (n - 1);
  spec.total_mass = 1.0;
  spec.stiffness_b = 1.0;
  append_cloth(s, spec);
  Step st;
  st.rest = s.particles.x;
  st.tris = s.triangles;
  st.x0 = folded(st.rest, kStartHeight[kind], 0.0);
  st.x1 = folded(st.rest, 0.02, kDrop[kind]);
  return cache.emplace(key, std::move(st)).first->second;
}

void continuous(benchmark::State& state, int kind) {
  const Step& st = step_of(static_cast<int>(state.range(0)), kind);
  ContinuousSelfCollisionDetector det(st.tris, st.rest);
  std::size_t pairs = 0;
  for (auto _ : state) {
    const ContinuousContacts& c = det.detect(st.x0, st.x1);
    pairs = c.vertex_face.size() + c.edge_edge.size();
    benchmark::DoNotOptimize(pairs);
  }
  state.counters["pairs"] = static_cast<double>(pairs);
  state.counters["tests"] = static_cast<double>(det.last_tests());
  state.counters["tree_pairs"] = static_cast<double>(det.last_triangle_pairs());
}

void confirmed(benchmark::State& state) {
  const Step& st = step_of(static_cast<int>(state.range(0)), 0);
  ContinuousSelfCollisionDetector det(st.tris, st.rest);
  std::size_t pairs = 0;
  for (auto _ : state) {
    const ContinuousContacts c = filter_contacts(det.detect(st.x0, st.x1), st.x0, st.x1, st.tris, &reference::exact_ccd_hit);
    pairs = c.vertex_face.size() + c.edge_edge.size();
    benchmark::DoNotOptimize(pairs);
  }
  state.counters["pairs"] = static_cast<double>(pairs);
}

void continuous_threads(benchmark::State& state, int threads) {
  const Step& st = step_of(static_cast<int>(state.range(0)), 0);
  ContinuousSelfCollisionDetector det(st.tris, st.rest);
  det.set_threads(threads);
  std::size_t pairs = 0;
  for (auto _ : state) {
    const ContinuousContacts& c = det.detect(st.x0, st.x1);
    pairs = c.vertex_face.size() + c.edge_edge.size();
    benchmark::DoNotOptimize(pairs);
  }
  state.counters["pairs"] = static_cast<double>(pairs);
}

void discrete_threads(benchmark::State& state, int threads) {
  const Step& st = step_of(static_cast<int>(state.range(0)), 0);
  SelfCollisionDetector det(st.tris, st.rest);
  det.set_threads(threads);
  std::size_t pairs = 0;
  for (auto _ : state) {
    pairs = det.detect(st.x1).size();
    benchmark::DoNotOptimize(pairs);
  }
  state.counters["pairs"] = static_cast<double>(pairs);
}

void discrete(benchmark::State& state, int kind) {
  const Step& st = step_of(static_cast<int>(state.range(0)), kind);
  SelfCollisionDetector det(st.tris, st.rest);
  std::size_t pairs = 0;
  for (auto _ : state) {
    pairs = det.detect(st.x1).size();
    benchmark::DoNotOptimize(pairs);
  }
  state.counters["pairs"] = static_cast<double>(pairs);
  state.counters["candidates"] = static_cast<double>(det.last_candidates());
}

const int registered = [] {
  for (int n : {32, 64, 128, 256}) {
    benchmark::RegisterBenchmark("BM_ContinuousSelfCollision/core", continuous, 0)->Arg(n)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("BM_ContinuousSelfCollision/discrete", discrete, 0)->Arg(n)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("BM_ContinuousSelfCollision/confirmed", confirmed)->Arg(n)->Unit(benchmark::kMillisecond);
  }
  for (int t : {1, 2}) {
    const std::string suffix = ":" + std::to_string(t);
    benchmark::RegisterBenchmark(("BM_ContinuousSelfCollision/threads" + suffix).c_str(), continuous_threads, t)
        ->Arg(256)
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("BM_ContinuousSelfCollision/discrete-threads" + suffix).c_str(), discrete_threads, t)
        ->Arg(256)
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond);
  }
  for (int n : {32, 64, 128, 256}) {
    benchmark::RegisterBenchmark("BM_ContinuousSelfCollision/core-gentle", continuous, 1)->Arg(n)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("BM_ContinuousSelfCollision/discrete-gentle", discrete, 1)->Arg(n)->Unit(benchmark::kMillisecond);
  }
  return 0;
}();

}  // namespace
