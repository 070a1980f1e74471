// Self-collision detection over a long run: per-step cost with the detectors kept from step to
// step (the box tree built once and refitted, buffers reused: what a simulation with
// self-collision does, core/simulation/self_collision_response.h) against detection from
// scratch (a detector built on the step's start positions, then one detect).
//
//   BM_SelfCollisionLongRun/<scene>/<detection>
// scenes: `experiment`, the seed's experiment scene (data/scenes/seed_fig21_self_contact.json,
// 16 x 16 cloth in a circling wind, 1000 steps of 0.01 s); `fold128`, a 128 x 128 cloth falling
// onto itself (bench/scenes/cloth_fold_128.json, not in data/scenes: no test runs it whole; 1000 steps of 0.5 ms). Each scene's motion is
// simulated without its self-collision response (the detectors only watch). detection:
// `discrete` (the intersecting triangle pairs of each step's end frame, self_collision.h) or
// `continuous` (the contacts during each step, continuous_self_collision.h). fold128 is minutes
// of its own, and most of them are the simulation's (its spring forces took 60-70% of a profile;
// detecting over the last 100 steps alone still took over 2 min CPU): the `bench` suite leaves it
// out.
// One iteration is the whole run; the simulation's own steps are outside the timed sections.
// Counters: `reuse_us` and `scratch_us`, mean detection time per step (steady clock), `ratio`
// = scratch / reuse, and `pairs` summed over the run. Both ways must report the same pairs at
// every step; the benchmark stops with an error otherwise.
#include "comparisons/io/source_dir.h"
#include "comparisons/io/scene_json.h"
#include "core/cloth/continuous_self_collision.h"
#include "core/cloth/self_collision.h"
#include "core/simulation/simulation.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <string>

namespace {

using namespace tecido;
using LongRunClock = std::chrono::steady_clock;

double micros_since(LongRunClock::time_point t0) {
  return std::chrono::duration<double, std::micro>(LongRunClock::now() - t0).count();
}

Scene long_run_scene(const std::string& file) {
  Scene s = io::load_scene(std::string(TECIDO_SOURCE_DIR) + "/" + file);
  s.self_collision.reset();  // the motion alone: the detectors watch it
  return s;
}

bool all_finite(const std::vector<Vec3>& x) {
  return std::all_of(x.begin(), x.end(), [](const Vec3& p) { return p.allFinite(); });
}

/// Sizes of one step's answer from the kept detector and from a fresh one; false if they differ.
struct StepCost {
  double reuse_us = 0, scratch_us = 0;
  std::size_t pairs = 0;
  bool same = true;
};

StepCost discrete_step(SelfCollisionDetector& kept, const Scene& s, const std::vector<Vec3>&, const std::vector<Vec3>& x1) {
  StepCost c;
  auto t0 = LongRunClock::now();
  const std::vector<TrianglePair> a = kept.detect(x1);
  c.reuse_us = micros_since(t0);
  t0 = LongRunClock::now();
  SelfCollisionDetector fresh(s.triangles, x1);
  const std::vector<TrianglePair>& b = fresh.detect(x1);
  c.scratch_us = micros_since(t0);
  c.pairs = a.size();
  c.same = a == b;
  return c;
}

StepCost continuous_step(ContinuousSelfCollisionDetector& kept, const Scene& s, const std::vector<Vec3>& x0,
                         const std::vector<Vec3>& x1) {
  StepCost c;
  auto t0 = LongRunClock::now();
  const ContinuousContacts a = kept.detect(x0, x1);
  c.reuse_us = micros_since(t0);
  t0 = LongRunClock::now();
  ContinuousSelfCollisionDetector fresh(s.triangles, x0);
  const ContinuousContacts& b = fresh.detect(x0, x1);
  c.scratch_us = micros_since(t0);
  c.pairs = a.vertex_face.size() + a.edge_edge.size();
  c.same = a == b;
  return c;
}

template <class Detector, class StepFn>
void long_run(benchmark::State& state, const std::string& file, StepFn step_fn) {
  const Scene scene = long_run_scene(file);
  double reuse = 0, scratch = 0, pairs = 0;
  long long steps = 0;
  for (auto _ : state) {
    Simulation sim(scene);
    Detector kept(scene.triangles, sim.particles().x);
    std::vector<Vec3> x0 = sim.particles().x;
    for (long long k = 0; k < scene.steps; ++k) {
      if (!sim.step() || !all_finite(sim.particles().x)) {
        state.SkipWithError("the simulation became unstable");
        return;
      }
      const StepCost c = step_fn(kept, scene, x0, sim.particles().x);
      if (!c.same) {
        state.SkipWithError("kept and fresh detectors disagree");
        return;
      }
      reuse += c.reuse_us;
      scratch += c.scratch_us;
      pairs += static_cast<double>(c.pairs);
      ++steps;
      x0 = sim.particles().x;
    }
  }
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["reuse_us"] = reuse / static_cast<double>(std::max(1LL, steps));
  state.counters["scratch_us"] = scratch / static_cast<double>(std::max(1LL, steps));
  state.counters["ratio"] = scratch / std::max(1e-9, reuse);
  state.counters["pairs"] = pairs;
}

const int registered = [] {
  const std::pair<const char*, const char*> scenes[] = {{"experiment", "data/scenes/seed_fig21_self_contact.json"},
                                                        {"fold128", "bench/scenes/cloth_fold_128.json"}};
  for (const auto& [name, file] : scenes) {
    const std::string f = file;
    benchmark::RegisterBenchmark((std::string("BM_SelfCollisionLongRun/") + name + "/discrete").c_str(),
                                 [f](benchmark::State& st) { long_run<SelfCollisionDetector>(st, f, discrete_step); })
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string("BM_SelfCollisionLongRun/") + name + "/continuous").c_str(),
                                 [f](benchmark::State& st) {
                                   long_run<ContinuousSelfCollisionDetector>(st, f, continuous_step);
                                 })
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
  }
  return 0;
}();

}  // namespace
