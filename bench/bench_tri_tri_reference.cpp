// Reference triangle-triangle engines on the core benchmark's fixed random pairs:
// BM_TriTri/fcl, BM_TriTri/ccd-gjk, BM_TriTri/ccd-mpr, BM_TriTri/exact. One iteration = one
// pair (cycling through the set), so the reported time is ns per pair.

#include "bench/random_pairs.h"
#include "reference/ccd_adapter.h"
#include "reference/exact_referee.h"
#include "reference/fcl_adapter.h"

#include <benchmark/benchmark.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace {

using tecido::Triangle;

/// The core benchmark's 10^5 pairs (bench/random_pairs.h: std::mt19937_64 seeded 42,
/// (x >> 11) * 2^-53 per coordinate, six unit-cube points per pair).
const std::vector<tecido::bench::TrianglePair>& pairs() { return tecido::bench::default_random_pairs(); }

template <class Test>
void run(benchmark::State& state, Test test) {
  const auto& set = pairs();
  std::size_t i = 0;
  std::int64_t hits = 0;
  for (auto _ : state) {
    const auto& p = set[i];
    const auto r = test(p.a, p.b);
    benchmark::DoNotOptimize(r);
    hits += r;
    if (++i == set.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["pairs"] = static_cast<double>(set.size());
  // Share of timed pairs reported intersecting: on these general-position pairs every engine
  // should match the core's (a quick check that all benchmarks time the same input).
  state.counters["hit_share"] = static_cast<double>(hits) / static_cast<double>(state.iterations());
}

bool as_bool(bool b) { return b; }
bool as_bool(const std::optional<bool>& b) { return b.value_or(false); }

template <class F>
auto wrap(F f) {
  return [f](const Triangle& a, const Triangle& b) { return as_bool(f(a, b)); };
}

const bool registered = [] {
  benchmark::RegisterBenchmark("BM_TriTri/fcl",
                               [](benchmark::State& s) { run(s, wrap(tecido::reference::fcl_tri_tri)); });
  benchmark::RegisterBenchmark("BM_TriTri/ccd-gjk",
                               [](benchmark::State& s) { run(s, wrap(tecido::reference::ccd_gjk_tri_tri)); });
  benchmark::RegisterBenchmark("BM_TriTri/ccd-mpr",
                               [](benchmark::State& s) { run(s, wrap(tecido::reference::ccd_mpr_tri_tri)); });
  benchmark::RegisterBenchmark("BM_TriTri/exact",
                               [](benchmark::State& s) { run(s, wrap(tecido::reference::exact_tri_tri)); });
  return true;
}();

}  // namespace

