// Cloth self-collision detection per frame: broad phase (refitted box tree) + exact narrow
// phase, on an n x n grid cloth folded over itself with a ripple, so the two layers cross
// along curves (a crumpled frame's worst case: every triangle has a near neighbour layer).
#include "core/cloth/self_collision.h"
#include "core/scene/cloth_builder.h"
#include "reference/fcl_adapter.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

namespace {

using namespace tecido;

struct Frame {
  std::vector<Vec3> rest, x;
  std::vector<std::array<int, 3>> tris;
};

// n x n cloth of side 1 m: folded at u = 0.5 so the right half lies back over the left half,
// 0.02 m above it, with a ripple of amplitude 0.03 m: the layers cross along curves.
Frame folded_cloth(int n) {
  Scene s;
  append_cloth(s, unit_square_cloth(n));
  Frame f;
  f.rest = s.particles.x;
  f.tris = s.triangles;
  f.x = f.rest;
  for (auto& p : f.x) {
    const double u = p.x(), v = p.y();
    const double ripple = 0.03 * std::sin(9.0 * u + 1.0) * std::sin(7.0 * v);
    if (u <= 0.5) {
      p = Vec3(u, v, ripple);
    } else {
      const double a = (u - 0.5) / 0.02;  // a tight half-turn of radius 0.01 then back
      if (a < M_PI) {
        p = Vec3(0.5 + 0.01 * std::sin(a), v, 0.01 - 0.01 * std::cos(a) + ripple);
      } else {
        p = Vec3(0.5 - (u - 0.5 - 0.02 * M_PI), v, 0.02 - ripple);
      }
    }
  }
  return f;
}

// BM_SelfCollision/<engine>/<n>: one frame of the folded n x n cloth.
//   core       refitted box tree + exact narrow phase (the tree is built once, outside the loop)
//   core-flat  the same on the flat rest shape (every neighbour box overlaps: the broad phase's worst case)
//   core-brute all pairs + exact narrow phase (n <= 64)
//   fcl        FCL's OBBRSS BVH of the mesh against itself, adjacent pairs filtered (reference build)
void core_frame(benchmark::State& state, bool flat) {
  const Frame f = folded_cloth(static_cast<int>(state.range(0)));
  SelfCollisionDetector det(f.tris, f.rest);
  std::size_t pairs = 0;
  for (auto _ : state) {
    pairs = det.detect(flat ? f.rest : f.x).size();
    benchmark::DoNotOptimize(pairs);
  }
  state.counters["triangles"] = static_cast<double>(f.tris.size());
  state.counters["pairs"] = static_cast<double>(pairs);
  state.counters["candidates"] = static_cast<double>(det.last_candidates());
}

// BM_SelfCollision/bvh-threads:<t>/<n>: the broad phase alone (refit + self-query of the box
// tree) of the folded frame on t threads (wall time), for the threads' speed-up of the part
// the tree does.
void bvh_threads(benchmark::State& state, int threads) {
  const Frame f = folded_cloth(static_cast<int>(state.range(0)));
  TriangleBvh bvh;
  bvh.build(f.rest, f.tris);
  std::vector<std::array<int, 2>> pairs;
  for (auto _ : state) {
    bvh.refit(f.x);
    pairs.clear();
    bvh.overlapping_pairs(pairs, threads);
    benchmark::DoNotOptimize(pairs.data());
  }
  state.counters["candidates"] = static_cast<double>(pairs.size());
  state.counters["parts"] = bvh.last_parts();
}

void brute_frame(benchmark::State& state) {
  const Frame f = folded_cloth(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(self_collision_pairs_brute(f.x, f.tris).size());
  state.counters["triangles"] = static_cast<double>(f.tris.size());
}

void fcl_frame(benchmark::State& state) {
  const Frame f = folded_cloth(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(reference::fcl_self_collision(f.x, f.tris).size());
  state.counters["triangles"] = static_cast<double>(f.tris.size());
}

const int registered = [] {
  for (int n : {32, 64, 128, 256}) {
    benchmark::RegisterBenchmark("BM_SelfCollision/core", core_frame, false)->Arg(n)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("BM_SelfCollision/core-flat", core_frame, true)->Arg(n)->Unit(benchmark::kMillisecond);
    for (int t : {1, 2})
      if (n >= 128)
        benchmark::RegisterBenchmark(("BM_SelfCollision/bvh-threads:" + std::to_string(t)).c_str(), bvh_threads, t)
            ->Arg(n)->Unit(benchmark::kMillisecond)->UseRealTime();
    if (n <= 64) benchmark::RegisterBenchmark("BM_SelfCollision/core-brute", brute_frame)->Arg(n)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("BM_SelfCollision/fcl", fcl_frame)->Arg(n)->Unit(benchmark::kMillisecond);
  }
  return 0;
}();

}  // namespace
