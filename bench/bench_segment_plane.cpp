// Segment versus bounded plane on a fixed set of 10^5 random cases, one case per iteration,
// cycling through the set, so the reported time is the time per call; items/s counts calls.
//   BM_SegmentPlane/core       exact decision: filtered signs, exact dyadic fallback
//                              (core/geometry/segment_plane.h)
//   BM_SegmentPlane/core-seed  the seed's floating-point test as written
//                              (core/geometry/segment_plane_seed.h)
// The cases are those of the plane suite's random category, drawn here with std::mt19937_64
// seeded 7: a plane centred in [-0.5, 0.5]^3 with a random unit normal and forward (at least
// 0.1 apart from parallel, orthogonalised by make_bounded_plane), half extents in [0.1, 2],
// end points in [-2.5, 2.5]^3. Counters (outside the timed loop): `hit_share`, and for core
// `exact_share`, the share of calls the filter could not decide.
#include "core/geometry/segment_plane.h"
#include "core/geometry/segment_plane_seed.h"

#include <benchmark/benchmark.h>

#include <cstdint>
#include <random>
#include <vector>

namespace {

using tecido::BoundedPlane;
using tecido::Vec2;
using tecido::Vec3;

struct PlaneCase {
  BoundedPlane plane;
  Vec3 from, to;
};

std::vector<PlaneCase> random_plane_cases(std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto uniform = [&rng](double a, double b) { return a + (b - a) * (static_cast<double>(rng() >> 11) * 0x1.0p-53); };
  auto in_box = [&](double lo, double hi) { return Vec3(uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)); };
  auto unit_vector = [&] {
    for (;;) {
      const Vec3 v = in_box(-1.0, 1.0);
      const double n = v.norm();
      if (n > 1e-3 && n <= 1.0) return Vec3(v / n);
    }
  };
  std::vector<PlaneCase> cases(count);
  for (PlaneCase& c : cases) {
    const Vec3 n = unit_vector();
    Vec3 f = unit_vector();
    while (n.cross(f).norm() < 0.1) f = unit_vector();
    const Vec3 centre = in_box(-0.5, 0.5);
    const Vec2 half(uniform(0.1, 2.0), uniform(0.1, 2.0));
    c.plane = tecido::make_bounded_plane(centre, n, f, half, 0.0);
    c.from = in_box(-2.5, 2.5);
    c.to = in_box(-2.5, 2.5);
  }
  return cases;
}

const std::vector<PlaneCase>& default_cases() {
  static const std::vector<PlaneCase> cases = random_plane_cases(100000, 7);
  return cases;
}

using SegmentPlaneFn = tecido::SegmentPlaneHit (*)(const BoundedPlane&, const Vec3&, const Vec3&);

void run_segment_plane(benchmark::State& state, SegmentPlaneFn fn, bool count_exact) {
  const auto& cases = default_cases();
  const std::size_t n = cases.size();
  std::size_t i = 0;
  for (auto _ : state) {
    const PlaneCase& c = cases[i];
    benchmark::DoNotOptimize(fn(c.plane, c.from, c.to));
    if (++i == n) i = 0;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));

  std::size_t hits = 0, exact = 0;
  for (const PlaneCase& c : cases) {
    const std::uint64_t before = tecido::segment_plane_exact_path_count();
    hits += fn(c.plane, c.from, c.to).hit;
    exact += tecido::segment_plane_exact_path_count() != before;
  }
  state.counters["hit_share"] = static_cast<double>(hits) / static_cast<double>(n);
  if (count_exact) state.counters["exact_share"] = static_cast<double>(exact) / static_cast<double>(n);
}

const bool registered = [] {
  benchmark::RegisterBenchmark("BM_SegmentPlane/core", run_segment_plane, &tecido::segment_plane, true);
  benchmark::RegisterBenchmark("BM_SegmentPlane/core-seed", run_segment_plane, &tecido::segment_plane_seed, false);
  return true;
}();

}  // namespace
