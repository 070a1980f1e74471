#include "comparisons/suites/tritri_suite.h"

#include "comparisons/engines/tri_tri_engines.h"
#include "comparisons/io/atomic_file.h"
#include "comparisons/suites/plane_suite.h"
#include "comparisons/suites/random.h"
#include "comparisons/suites/sweep.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>

namespace tecido::suites {

namespace {

/// Small integers: every sum and product of a few of them is exact in double.
Vec3 lattice(Rng& r, int span) {
  return Vec3(static_cast<double>(r.below(2 * span + 1)) - span, static_cast<double>(r.below(2 * span + 1)) - span,
              static_cast<double>(r.below(2 * span + 1)) - span);
}

Triangle lattice_triangle(Rng& r, int span) {
  for (;;) {
    Triangle t{lattice(r, span), lattice(r, span), lattice(r, span)};
    if ((t[1] - t[0]).cross(t[2] - t[0]).squaredNorm() > 0) return t;
  }
}

}  // namespace

std::vector<io::TriPair> make_tri_pairs(std::uint64_t seed, int n_random, int n_per_category) {
  std::vector<io::TriPair> out;
  out.reserve(static_cast<std::size_t>(n_random) + 7u * n_per_category);
  const char* cats[] = {"random", "near-coplanar", "coplanar", "touch-vertex", "touch-edge", "shared-vertex", "sliver", "offset"};
  for (std::uint64_t ci = 0; ci < 8; ++ci) {
    const std::string cat = cats[ci];
    const int n = ci == 0 ? n_random : n_per_category;
    Rng stream(substream(seed, 1000 + ci));  // one stream per category: cases depend on (seed, category, k) only
    for (int k = 0; k < n; ++k) {
      Rng r(stream.next());
      io::TriPair p;
      p.id = cat + "/" + std::to_string(k);
      if (cat == "random") {
        p.a = {r.in_box(0, 1), r.in_box(0, 1), r.in_box(0, 1)};
        p.b = {r.in_box(0, 1), r.in_box(0, 1), r.in_box(0, 1)};
      } else if (cat == "near-coplanar") {
        // b lies in a's plane up to a tiny normal offset (1e-16 .. 1e-6, either side, per vertex).
        p.a = {r.in_box(0, 1), r.in_box(0, 1), r.in_box(0, 1)};
        const Vec3 n = (p.a[1] - p.a[0]).cross(p.a[2] - p.a[0]).normalized();
        const Vec3 u = (p.a[1] - p.a[0]).normalized(), v = n.cross(u);
        for (auto& q : p.b) {
          q = p.a[0] + r.uniform(-0.5, 1.2) * u + r.uniform(-0.5, 1.2) * v +
              std::pow(10.0, r.uniform(-16, -6)) * (r.below(2) ? 1.0 : -1.0) * n;
        }
      } else if (cat == "coplanar") {
        // Exactly coplanar: integer combinations of two integer vectors from an integer origin.
        const Vec3 o = lattice(r, 8), u = lattice(r, 3), v = lattice(r, 3);
        if (u.cross(v).squaredNorm() == 0) {
          --k;
          continue;
        }
        auto pt = [&]() { return o + (static_cast<double>(r.below(9)) - 4) * u + (static_cast<double>(r.below(9)) - 4) * v; };
        p.a = {pt(), pt(), pt()};
        p.b = {pt(), pt(), pt()};
      } else if (cat == "touch-vertex") {
        // A vertex of b exactly on a's face (dyadic barycentric point of a lattice triangle),
        // the rest of b on one side of a's plane or across it.
        p.a = lattice_triangle(r, 6);
        const double w0 = std::ldexp(static_cast<double>(r.below(5)), -2);
        const double w1 = std::ldexp(static_cast<double>(r.below(5 - static_cast<int>(w0 * 4))), -2);
        const Vec3 on = p.a[0] + w1 * (p.a[1] - p.a[0]) + (1.0 - w0 - w1 >= 0 ? w0 : 0.0) * (p.a[2] - p.a[0]);
        const Vec3 n = (p.a[1] - p.a[0]).cross(p.a[2] - p.a[0]);
        const double side = r.below(2) ? 1.0 : -1.0;
        p.b = {on, on + side * n.normalized() * r.uniform(0.5, 3) + lattice(r, 2), on + side * n.normalized() * r.uniform(0.5, 3) + lattice(r, 2)};
      } else if (cat == "touch-edge") {
        // b's edge passes exactly through the midpoint of an edge of a (lattice points, so the
        // midpoint is exact), b otherwise above, below or across a's plane.
        p.a = lattice_triangle(r, 6);
        const int e = static_cast<int>(r.below(3));
        const Vec3 m = 0.5 * (p.a[e] + p.a[(e + 1) % 3]);
        const Vec3 d = lattice(r, 3);
        p.b = {m - d, m + d, m + lattice(r, 4)};
        if ((p.b[1] - p.b[0]).cross(p.b[2] - p.b[0]).squaredNorm() == 0) p.b[2] += Vec3(1, 2, 3);
      } else if (cat == "shared-vertex") {
        p.a = {r.in_box(-1, 1), r.in_box(-1, 1), r.in_box(-1, 1)};
        p.b = {p.a[r.below(3)], r.in_box(-1, 1), r.in_box(-1, 1)};
      } else if (cat == "sliver") {
        // Nearly or exactly collinear triangles against random ones and against each other.
        auto sliver = [&]() {
          const Vec3 s = r.in_box(0, 1), e = r.in_box(0, 1);
          const double eps = r.below(4) == 0 ? 0.0 : std::pow(10.0, r.uniform(-15, -5));
          return Triangle{s, e, s + r.uniform(0, 1) * (e - s) + eps * r.unit_vector()};
        };
        p.a = sliver();
        p.b = r.below(2) ? sliver() : Triangle{r.in_box(0, 1), r.in_box(0, 1), r.in_box(0, 1)};
      } else {  // offset: unit-size pairs far from the origin
        const Vec3 shift = std::pow(10.0, 3 + static_cast<double>(k % 6)) * r.unit_vector();
        for (auto& q : p.a) q = shift + r.in_box(0, 1);
        for (auto& q : p.b) q = shift + r.in_box(0, 1);
      }
      out.push_back(std::move(p));
    }
  }
  return out;
}

namespace {

/// Pairs per case: each case runs every engine on one contiguous block of the pairs.
constexpr std::size_t kBlock = 10000;
/// At most this many disagreements are kept (in engine order, then pair order).
constexpr std::size_t kMaxDisagreements = 100000;
const std::vector<std::string>& categories() {
  static const std::vector<std::string> cats = {"random", "near-coplanar", "coplanar", "touch-vertex", "touch-edge",
                                                "shared-vertex", "sliver", "offset"};
  return cats;
}

/// What every case and the assembly share: the pairs (generated once per process from the seed).
struct TritriPlan {
  SuiteContext ctx;
  int n_random = 0, n_cat = 0;
  std::vector<io::TriPair> pairs;
  const TriTriEngine* referee = nullptr;
};

/// Case k: the referee and every engine on pairs [k kBlock, (k+1) kBlock). Result:
/// {"true":{category: intersecting pairs}, "engines":[{"random_seconds": wall s over this block's
/// random pairs, "tally":{category:[agree, pairs, no answer]}, "disagree":[pair index, ...]}]}.
io::Json tritri_case(const TritriPlan& plan, std::size_t k) {
  const std::size_t b0 = k * kBlock, b1 = std::min(plan.pairs.size(), b0 + kBlock);
  const std::size_t r1 = std::min(b1, std::max(b0, static_cast<std::size_t>(plan.n_random)));  // random pairs: [b0, r1)
  const auto& pairs = plan.pairs;
  std::vector<char> truth(b1 - b0);
  std::vector<std::string> cat(b1 - b0);
  io::Json true_count = io::Json::object();
  for (std::size_t i = b0; i < b1; ++i) {
    truth[i - b0] = plan.referee->test(pairs[i].a, pairs[i].b).value_or(false);
    cat[i - b0] = case_category(pairs[i].id);
    true_count[cat[i - b0]] = true_count.value(cat[i - b0], 0L) + truth[i - b0];
  }
  io::Json engines = io::Json::array();
  for (const auto& eng : tri_tri_engines()) {
    std::vector<std::optional<bool>> got(b1 - b0);
    // Time the random pairs alone (contiguous at the front of the pairs).
    const auto t0 = std::chrono::steady_clock::now();
    for (std::size_t i = b0; i < r1; ++i) got[i - b0] = eng.test(pairs[i].a, pairs[i].b);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    for (std::size_t i = r1; i < b1; ++i) got[i - b0] = eng.test(pairs[i].a, pairs[i].b);
    std::map<std::string, std::array<long, 3>> tally;  // agree, total, null
    io::Json disagree = io::Json::array();
    for (std::size_t i = b0; i < b1; ++i) {
      auto& t = tally[cat[i - b0]];
      ++t[1];
      if (!got[i - b0]) {
        ++t[2];
      } else if (*got[i - b0] == static_cast<bool>(truth[i - b0])) {
        ++t[0];
      } else if (eng.name != "exact" && disagree.size() < kMaxDisagreements) {
        disagree.push_back(i);
      }
    }
    io::Json jt = io::Json::object();
    for (const auto& [c, t] : tally) jt[c] = {t[0], t[1], t[2]};
    engines.push_back({{"random_seconds", seconds}, {"tally", jt}, {"disagree", disagree}});
  }
  return {{"true", true_count}, {"engines", engines}};
}

SuiteResult tritri_assemble(const TritriPlan& plan, const std::vector<io::Json>& results) {
  SuiteResult res;
  res.name = "tritri";
  const SuiteContext& ctx = plan.ctx;
  const Tolerances& tol = *ctx.tolerances;
  if (!plan.referee) {
    res.markdown = "The exact referee is not built in (reference adapters off): no agreement measured.\n";
    return res;
  }
  const auto& cats = categories();
  const auto& pairs = plan.pairs;
  const int n_random = plan.n_random;
  std::map<std::string, long> true_count;
  for (const auto& r : results)
    for (auto it = r.at("true").begin(); it != r.at("true").end(); ++it) true_count[it.key()] += it.value().get<long>();

  std::string md;
  md += fmt::format("{} random pairs in the unit cube and {} pairs of each adversarial family (seed {}). Each cell: pairs "
                    "where the engine agrees with the exact referee (CGAL exact predicates) / pairs; `n/a` = engine gave no "
                    "answer. ns/pair: mean over the random pairs, one thread, this run.\n\n",
                    n_random, plan.n_cat, ctx.seed);
  md += "| engine | ns/pair |";
  for (const auto& c : cats) md += " " + c + " |";
  md += "\n|---|---:|";
  for (std::size_t i = 0; i < cats.size(); ++i) md += "---:|";
  md += "\n| (exact: intersecting) | |";
  for (const auto& c : cats) md += fmt::format(" {} |", true_count[c]);
  md += "\n";

  std::vector<io::TriPair> disagreements;
  io::Json data = io::Json::object();
  const auto& engines = tri_tri_engines();
  for (std::size_t e = 0; e < engines.size(); ++e) {
    const auto& eng = engines[e];
    double seconds = 0.0;
    std::map<std::string, std::array<long, 3>> tally;  // agree, total, null
    for (const auto& r : results) {
      const io::Json& je = r.at("engines").at(e);
      seconds += je.at("random_seconds").get<double>();
      for (auto it = je.at("tally").begin(); it != je.at("tally").end(); ++it)
        for (int q = 0; q < 3; ++q) tally[it.key()][q] += it.value().at(q).get<long>();
      for (const auto& i : je.at("disagree")) {
        if (disagreements.size() >= kMaxDisagreements) break;
        io::TriPair d = pairs.at(i.get<std::size_t>());
        d.id = eng.name + ":" + d.id;
        disagreements.push_back(d);
      }
    }
    const double ns = 1e9 * seconds / n_random;
    md += fmt::format("| {} | {:.0f} |", eng.name, ns);
    data[eng.name]["ns_per_pair"] = ns;
    for (const auto& c : cats) {
      const auto& t = tally[c];
      md += fmt::format(" {}/{}{} |", t[0], t[1], t[2] ? fmt::format(" ({} n/a)", t[2]) : "");
      data[eng.name][c] = {{"agree", t[0]}, {"pairs", t[1]}, {"no_answer", t[2]}};
      if (eng.name == "exact") continue;
      const std::string key = "/tritri/" + eng.name + "_min_agreement";
      const double rate = static_cast<double>(t[0]) / static_cast<double>(t[1]);
      if (eng.name == "core") {
        res.checks.push_back(make_check("tritri/core/agreement/" + c, rate, tol.get("/tritri/core_min_agreement"), 1.0));
      } else if (c == "random" && eng.name.rfind("core-", 0) != 0) {
        // The seed's own two tests are kept as written and reported, not checked: core-mt
        // requires both edge directions to hit (the seed's AND) and misses many crossings.
        res.checks.push_back(make_check("tritri/" + eng.name + "/agreement/random", rate, tol.get(key), 1.0));
      }
    }
    md += "\n";
  }
  io::write_file_atomic(ctx.out_dir + "/tritri/disagreements.json", io::tri_pairs_to_json(disagreements).dump() + "\n");
  md += fmt::format("\n{} disagreements with the referee are in `tritri/disagreements.json` (ids `engine:category/k`); "
                    "`tecido tritri --pairs out/tritri/disagreements.json --json` re-runs them with every engine.\n",
                    disagreements.size());
  res.markdown = md;
  res.data = data;
  return res;
}

}  // namespace

Sweep tritri_sweep(const SuiteContext& ctx) {
  auto plan = std::make_shared<TritriPlan>();
  plan->ctx = ctx;
  plan->n_random = ctx.quick ? 100000 : 1000000;
  plan->n_cat = ctx.quick ? 500 : 2000;
  plan->referee = find_tri_tri_engine("exact");
  Sweep s;
  if (plan->referee) {
    plan->pairs = make_tri_pairs(substream(ctx.seed, 2), plan->n_random, plan->n_cat);
    s.cases = (plan->pairs.size() + kBlock - 1) / kBlock;
  }
  s.run_case = [plan](std::size_t k) { return tritri_case(*plan, k); };
  s.assemble = [plan](const std::vector<io::Json>& results) { return tritri_assemble(*plan, results); };
  return s;
}

SuiteResult run_tritri_suite(const SuiteContext& ctx) { return run_sweep(&tritri_sweep, ctx, "tritri"); }

}  // namespace tecido::suites
