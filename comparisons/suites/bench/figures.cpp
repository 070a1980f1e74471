#include "comparisons/suites/bench/figures.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tecido::suites::bench {

void Span::add(double v) {
  if (std::isnan(v)) return;
  lo = count ? std::min(lo, v) : v;
  hi = count ? std::max(hi, v) : v;
  ++count;
}

namespace {
double ms(const std::vector<BenchRow>& rows, const std::string& name) {
  const BenchRow* r = find_row(rows, name);
  return r ? r->ns_per_iter / 1e6 : NAN;
}

/// ns per spring of the core symplectic step of each size in `rows`; the kernel label into `kernel`.
Span spring_span(const std::vector<BenchRow>& rows, const Settings& s, std::string& kernel) {
  Span span;
  for (int n : s.cloth_sizes) {
    const BenchRow* c = find_row(rows, fmt::format("BM_ClothStep/core-symplectic/{}", n));
    span.add(ns_per_spring(c));
    if (c && kernel.empty()) kernel = c->label;
  }
  return span;
}
}  // namespace

Figures derive_figures(const std::vector<BenchRow>& rows, const std::vector<BenchRow>& sse2_rows, const Settings& s) {
  Figures f;
  const std::string tt = "BM_TriTri/";
  for (const BenchRow& r : rows)
    if (r.name.compare(0, tt.size(), tt) == 0) f.tritri_ns.emplace_back(r.name.substr(tt.size()), ns_per_item(rows, r.name));
  const double core = ns_per_item(rows, "BM_TriTri/core");
  f.tritri_core_vs_fcl = core / ns_per_item(rows, "BM_TriTri/fcl");
  f.tritri_core_vs_exact = core / ns_per_item(rows, "BM_TriTri/exact");
  f.selfcollision_ms = ms(rows, "BM_SelfCollision/core/256");
  f.selfcollision_flat_ms = ms(rows, "BM_SelfCollision/core-flat/256");
  f.selfcollision_fcl_ms = ms(rows, "BM_SelfCollision/fcl/256");
  for (int n : s.cloth_sizes) {
    const BenchRow* c = find_row(rows, fmt::format("BM_ClothStep/core-symplectic/{}", n));
    const BenchRow* b = find_row(rows, fmt::format("BM_ClothStep/bullet-classic/{}", n));
    if (c && b) f.cloth_vs_bullet.add(c->ns_per_iter / b->ns_per_iter);
    f.bullet_ns_per_link.add(ns_per_spring(b));
  }
  f.ns_per_spring = spring_span(rows, s, f.kernel);
  f.sse2_ns_per_spring = spring_span(sse2_rows, s, f.sse2_kernel);
  return f;
}

}  // namespace tecido::suites::bench
