// Continuous self-collision of an n x n cloth over one step, next to discrete self-collision of
// one frame of the same step (the ratio is the cost of looking between the frames).
//
// The step (comparisons/suites/bench/folding_cloth.h; scripts/fold_frames.py writes the same
// frames as OBJ): a side of 1 m folded over itself along x = 0.5 with a ripple on both layers, the
// fold closing from H = 0.04 m to H = 0.02 m (the flap comes down 2 cm, 2.5 edge lengths at
// n = 128, 5 at 256) while the whole cloth falls by 1 cm: a fast fold; the layers pass through each
// other over a wide band (about 22k touching pairs at n = 128). The "gentle" step closes the fold
// from H = 0.0225 m and drops 2 mm (0.15 m/s and 0.12 m/s at 60 Hz).
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
//                                                   Both stop with an error when the answer differs
//                                                   from the one-thread answer (checked outside
//                                                   the timed loop).
// Both trees are built once on the rest shape, outside the timed loop. Counters: `pairs`
// (reported pairs), `tests` (primitive pairs handed to the continuous test), `tree_pairs`
// (triangle pairs sharing no vertex from the swept-box tree).
#include "comparisons/suites/bench/folding_cloth.h"
#include "core/cloth/continuous_self_collision.h"
#include "core/cloth/self_collision.h"
#include "reference/exact_ccd.h"

#include <benchmark/benchmark.h>

#include <map>
#include <string>

namespace {

using namespace tecido;

using Step = suites::bench::FoldingStep;

const Step& step_of(int n, int kind) {
  static std::map<int, Step> cache;
  const int key = 2 * n + kind;
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  return cache.emplace(key, suites::bench::folding_cloth_step(n, kind == 1)).first->second;
}

void continuous(benchmark::State& state, int kind) {
  const Step& st = step_of(static_cast<int>(state.range(0)), kind);
  ContinuousSelfCollisionDetector det(st.triangles, st.rest);
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
  ContinuousSelfCollisionDetector det(st.triangles, st.rest);
  std::size_t pairs = 0;
  for (auto _ : state) {
    const ContinuousContacts c = filter_contacts(det.detect(st.x0, st.x1), st.x0, st.x1, st.triangles, &reference::exact_ccd_hit);
    pairs = c.vertex_face.size() + c.edge_edge.size();
    benchmark::DoNotOptimize(pairs);
  }
  state.counters["pairs"] = static_cast<double>(pairs);
}

void continuous_threads(benchmark::State& state, int threads) {
  const Step& st = step_of(static_cast<int>(state.range(0)), 0);
  ContinuousSelfCollisionDetector one(st.triangles, st.rest), det(st.triangles, st.rest);
  det.set_threads(threads);
  if (!(det.detect(st.x0, st.x1) == one.detect(st.x0, st.x1))) {
    state.SkipWithError("the answer differs from the one-thread answer");
    return;
  }
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
  SelfCollisionDetector one(st.triangles, st.rest), det(st.triangles, st.rest);
  det.set_threads(threads);
  if (det.detect(st.x1) != one.detect(st.x1)) {
    state.SkipWithError("the answer differs from the one-thread answer");
    return;
  }
  std::size_t pairs = 0;
  for (auto _ : state) {
    pairs = det.detect(st.x1).size();
    benchmark::DoNotOptimize(pairs);
  }
  state.counters["pairs"] = static_cast<double>(pairs);
}

void discrete(benchmark::State& state, int kind) {
  const Step& st = step_of(static_cast<int>(state.range(0)), kind);
  SelfCollisionDetector det(st.triangles, st.rest);
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
