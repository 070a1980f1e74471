// Triangle-triangle tests of core on the fixed set of 10^5 random unit-cube pairs
// (bench/random_pairs.h). One pair per iteration, cycling through the set, so the reported
// time is the time per pair; items/s counts pairs.
//   BM_TriTri/core           exact Guigue-Devillers (core/geometry/tri_tri_intersect.h)
//   BM_TriTri/core-rotation  the seed's rotation test (core/geometry/tri_tri_rotation.h)
//   BM_TriTri/core-mt        the seed's Möller-Trumbore rule (core/geometry/tri_tri_moller_trumbore.h)
// Counters (computed outside the timed loop): `hit_share`, the share of pairs the engine calls
// intersecting; for core, `exact_share`, the share of pairs for which at least one predicate
// missed the floating-point filter and took the exact path.
#include "bench/random_pairs.h"
#include "core/geometry/orient_predicates.h"
#include "core/geometry/tri_tri_intersect.h"
#include "core/geometry/tri_tri_moller_trumbore.h"
#include "core/geometry/tri_tri_rotation.h"

#include <benchmark/benchmark.h>

#include <cstddef>

namespace {

using TriTriFn = bool (*)(const tecido::Triangle&, const tecido::Triangle&);

void run_tri_tri(benchmark::State& state, TriTriFn fn, bool count_exact) {
  const auto& pairs = tecido::bench::default_random_pairs();
  const std::size_t n = pairs.size();
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& pair = pairs[i];
    benchmark::DoNotOptimize(fn(pair.a, pair.b));
    if (++i == n) i = 0;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));

  std::size_t hits = 0, exact = 0;
  for (const auto& pair : pairs) {
    const std::uint64_t before = tecido::orient_exact_path_count();
    hits += fn(pair.a, pair.b);
    exact += tecido::orient_exact_path_count() != before;
  }
  state.counters["hit_share"] = static_cast<double>(hits) / static_cast<double>(n);
  if (count_exact) state.counters["exact_share"] = static_cast<double>(exact) / static_cast<double>(n);
}

const bool registered = [] {
  benchmark::RegisterBenchmark("BM_TriTri/core", run_tri_tri, &tecido::tri_tri_intersect, true);
  benchmark::RegisterBenchmark("BM_TriTri/core-rotation", run_tri_tri, &tecido::tri_tri_rotation,
                               false);
  benchmark::RegisterBenchmark("BM_TriTri/core-mt", run_tri_tri, &tecido::tri_tri_moller_trumbore,
                               false);
  return true;
}();

}  // namespace
