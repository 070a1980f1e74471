// Continuous collision tests on the fixed seeded query mix of bench/ccd_queries.h (20000 queries
// per kind: random, small-motion random, contacts, near misses, coplanar motion, degenerate).
// One query per iteration, cycling through the mix, so the reported time is the time per query
// on the mix; items/s counts queries.
//   BM_CCD/core/vertex-face, BM_CCD/core/edge-edge   core's test (core/geometry/ccd/ccd.h)
//   BM_CCD/core/<kind>/<category>                    the same on one category of the mix
//   BM_CCD/exact/<kind>, BM_CCD/fcl/<kind>           the exact referee (reference/exact_ccd.h) and
//                                                    FCL's intersect_VF/EE (reference/fcl_adapter.h),
//                                                    and per category, on the same queries
//   BM_CCD/bullet/vertex-face                        Bullet's bernsteinCCD (reference/bullet_ccd.h;
//                                                    Bullet has no edge-edge test)
// Counters (computed outside the timed loop): `hit_share`, the share of queries answered hit;
// for core, `inclusion_share`, the share that needed the inclusion search (degenerate motion),
// and `boxes_per_query`, its boxes per query of the set; on the whole mix (no category), against the
// exact referee's answers: `false_negatives` (a count: zero by construction) and
// `false_positive_share`, core's hits the referee rejects over the referee's negatives.
// Another engine is one more line in `registered`: register_engine("fcl", &fn, false, false) gives
// BM_CCD/fcl/vertex-face and BM_CCD/fcl/edge-edge (reference engines).
#include "bench/ccd_queries.h"
#include "core/geometry/ccd/ccd.h"
#include "reference/bullet_ccd.h"
#include "reference/exact_ccd.h"
#include "reference/fcl_adapter.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

namespace {

using tecido::CcdAnswer;
using tecido::CcdKind;
using tecido::CcdQuery;
using CcdFn = CcdAnswer (*)(const CcdQuery&);

std::vector<CcdQuery> select(CcdKind kind, const char* category) {
  std::vector<CcdQuery> out;
  for (const auto& lq : tecido::bench::default_ccd_query_mix(kind))
    if (category == nullptr || std::strcmp(lq.category, category) == 0) out.push_back(lq.query);
  return out;
}

CcdAnswer exact_ccd(const CcdQuery& q) { return tecido::reference::to_ccd_answer(tecido::reference::exact_ccd(q)); }

/// Core's false negatives (a count) and false positives over the referee's negatives, on `queries`.
void set_error_counters(benchmark::State& state, CcdFn fn, const std::vector<CcdQuery>& queries) {
  std::size_t negatives = 0, false_negatives = 0, false_positives = 0;
  for (const CcdQuery& q : queries) {
    const bool truth = exact_ccd(q).hit, hit = fn(q).hit;
    negatives += !truth;
    false_negatives += truth && !hit;
    false_positives += hit && !truth;
  }
  state.counters["false_negatives"] = static_cast<double>(false_negatives);
  state.counters["false_positive_share"] = static_cast<double>(false_positives) / static_cast<double>(std::max<std::size_t>(1, negatives));
}

void run_ccd(benchmark::State& state, CcdFn fn, CcdKind kind, const char* category, bool core_counters) {
  const std::vector<CcdQuery> queries = select(kind, category);
  const std::size_t n = queries.size();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(fn(queries[i]));
    if (++i == n) i = 0;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  std::size_t hits = 0, inclusion = 0;
  const tecido::CcdStats before = tecido::ccd_stats();
  for (const CcdQuery& q : queries) {
    const unsigned long long calls = tecido::ccd_stats().inclusion_calls;
    hits += fn(q).hit;
    inclusion += tecido::ccd_stats().inclusion_calls != calls;
  }
  state.counters["hit_share"] = static_cast<double>(hits) / static_cast<double>(n);
  if (core_counters) {
    state.counters["inclusion_share"] = static_cast<double>(inclusion) / static_cast<double>(n);
    state.counters["boxes_per_query"] =
        static_cast<double>(tecido::ccd_stats().inclusion_boxes - before.inclusion_boxes) / static_cast<double>(n);
    if (category == nullptr) set_error_counters(state, fn, queries);
  }
}

CcdAnswer core_ccd(const CcdQuery& q) { return tecido::ccd(q); }

CcdAnswer fcl_ccd(const CcdQuery& q) { return tecido::reference::fcl_ccd(q); }
/// Vertex-face only (registered for that kind alone).
CcdAnswer bullet_ccd(const CcdQuery& q) { return tecido::reference::bullet_ccd(q).value_or(CcdAnswer{}); }

/// BM_CCD/<name>/<kind> for both kinds (or vertex-face alone) and, with per_category,
/// BM_CCD/<name>/<kind>/<category>.
void register_engine(const char* name, CcdFn fn, bool core_counters, bool per_category, bool vertex_face_only = false) {
  const char* categories[] = {"random-large", "random-small", "contact", "near-miss", "coplanar", "degenerate"};
  for (const CcdKind kind : {CcdKind::VertexFace, CcdKind::EdgeEdge}) {
    if (vertex_face_only && kind != CcdKind::VertexFace) continue;
    const std::string base = std::string("BM_CCD/") + name + "/" + tecido::ccd_kind_name(kind);
    benchmark::RegisterBenchmark(base.c_str(), run_ccd, fn, kind, nullptr, core_counters);
    if (per_category)
      for (const char* c : categories)
        benchmark::RegisterBenchmark((base + "/" + c).c_str(), run_ccd, fn, kind, c, core_counters);
  }
}

const bool registered = [] {
  register_engine("core", &core_ccd, true, true);
  register_engine("exact", &exact_ccd, false, true);
  register_engine("fcl", &fcl_ccd, false, true);
  register_engine("bullet", &bullet_ccd, false, true, true);
  return true;
}();

}  // namespace
