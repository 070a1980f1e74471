#include "comparisons/suites/bench/goal_rows.h"

#include <fmt/format.h>

#include <cmath>

namespace tecido::suites::bench {

bool GoalRow::measured() const { return std::isfinite(value); }
bool GoalRow::met() const { return measured() && (at_least ? value >= target : value <= target); }

namespace {
double cpu_ratio(const std::vector<BenchRow>& rows, const std::string& a, const std::string& b) {
  const BenchRow *ra = find_row(rows, a), *rb = find_row(rows, b);
  return ra && rb && rb->ns_per_iter > 0 ? ra->ns_per_iter / rb->ns_per_iter : NAN;
}

/// Wall time of `one` over wall time of `two` (a speed-up).
double wall_ratio(const std::vector<BenchRow>& rows, const std::string& one, const std::string& two) {
  const BenchRow *a = find_row(rows, one), *b = find_row(rows, two);
  return a && b && b->real_ns_per_iter > 0 ? a->real_ns_per_iter / b->real_ns_per_iter : NAN;
}

double counter(const std::vector<BenchRow>& rows, const std::string& name, const std::string& key) {
  const BenchRow* r = find_row(rows, name);
  return r && r->counters.contains(key) ? r->counters[key].get<double>() : NAN;
}

double cpu_ms(const std::vector<BenchRow>& rows, const std::string& name) {
  const BenchRow* r = find_row(rows, name);
  return r ? r->ns_per_iter / 1e6 : NAN;
}

/// The rows of the goals the project set itself before issue 24 (tri-tri, one frame, the cloth step).
void add_core_goals(std::vector<GoalRow>& out, const std::vector<BenchRow>& rows, const Settings& s, const Goals& g) {
  const double core = ns_per_item(rows, "BM_TriTri/core");
  out.push_back({"tritri_core_over_fcl", "core tri-tri time / FCL's", core / ns_per_item(rows, "BM_TriTri/fcl"),
                 g.tritri_vs_fcl, false, "", "`BM_TriTri/core` / `BM_TriTri/fcl`, ns per pair"});
  out.push_back({"tritri_core_over_exact", "core tri-tri time / CGAL exact's", core / ns_per_item(rows, "BM_TriTri/exact"),
                 g.tritri_vs_exact, false, "", "`BM_TriTri/core` / `BM_TriTri/exact`"});
  out.push_back({"selfcollision_256_ms", "self-collision of a folded 256x256 frame, core, one thread",
                 cpu_ms(rows, "BM_SelfCollision/core/256"), g.selfcollision_256_ms, false, "ms", "`BM_SelfCollision/core/256`"});
  out.push_back({"selfcollision_flat_256_ms", "self-collision of the flat 256x256 frame, core, one thread",
                 cpu_ms(rows, "BM_SelfCollision/core-flat/256"), g.selfcollision_flat_256_ms, false, "ms",
                 "`BM_SelfCollision/core-flat/256`"});
  for (int n : s.cloth_sizes) {
    const std::string c = fmt::format("BM_ClothStep/core-symplectic/{}", n), b = fmt::format("BM_ClothStep/bullet-classic/{}", n);
    out.push_back({fmt::format("cloth_step_{}_core_over_bullet", n), fmt::format("cloth step {0}x{0}: core symplectic / Bullet classic", n),
                   cpu_ratio(rows, c, b), g.cloth_vs_bullet, false, "", fmt::format("`{}` / `{}`", c, b)});
    out.push_back({fmt::format("cloth_step_{}_ns_per_spring", n), fmt::format("cloth step {0}x{0}: core ns per spring", n),
                   ns_per_spring(find_row(rows, c)), g.ns_per_spring, false, "ns", fmt::format("`{}` per spring", c)});
  }
}

/// Continuous against discrete: the benchmark's step, the exact answer on a real-sized mesh, the whole process.
void add_continuous_goals(std::vector<GoalRow>& out, const std::vector<BenchRow>& rows, const Settings& s, const Goals& g) {
  const std::string cs = "BM_ContinuousSelfCollision/";
  const int n = s.continuous_n, p = s.process_n;
  out.push_back({fmt::format("continuous_{}_over_discrete", n),
                 fmt::format("continuous self-collision {0}x{0}, core's detection / discrete of the end frame", n),
                 cpu_ratio(rows, fmt::format("{}core/{}", cs, n), fmt::format("{}discrete/{}", cs, n)), g.continuous_over_discrete,
                 false, "", fmt::format("`{0}core/{1}` / `{0}discrete/{1}`", cs, n)});
  out.push_back({fmt::format("continuous_exact_{}_over_discrete", n),
                 fmt::format("the same with its exact answer (core, then the referee's confirmation), {} triangles / discrete",
                             2 * (n - 1) * (n - 1)),
                 cpu_ratio(rows, fmt::format("{}confirmed/{}", cs, n), fmt::format("{}discrete/{}", cs, n)), g.continuous_over_discrete,
                 false, "", fmt::format("`{0}confirmed/{1}` / `{0}discrete/{1}`", cs, n)});
  const std::string one = fmt::format("process/selfcollide/continuous/threads:1/{}", p), d = fmt::format("process/selfcollide/discrete/{}", p);
  out.push_back({fmt::format("selfcollide_process_{}_over_discrete", p),
                 fmt::format("whole `selfcollide` process, {} triangles: `--to` (one thread) / discrete of the end frame, CPU",
                             2 * (p - 1) * (p - 1)),
                 cpu_ratio(rows, one, d), g.continuous_over_discrete, false, "", fmt::format("`{}` / `{}`, CPU time", one, d)});
}

/// Core's continuous test against FCL's, and its errors against the referee, per kind.
void add_ccd_goals(std::vector<GoalRow>& out, const std::vector<BenchRow>& rows, const Goals& g) {
  for (const char* kind : {"vertex-face", "edge-edge"}) {
    const std::string id = kind == std::string("edge-edge") ? "edge_edge" : "vertex_face";
    const std::string core = fmt::format("BM_CCD/core/{}", kind), fcl = fmt::format("BM_CCD/fcl/{}", kind);
    out.push_back({fmt::format("ccd_{}_core_over_fcl", id), fmt::format("continuous test {}: core time / FCL's per query on the mix", kind),
                   ns_per_item(rows, core) / ns_per_item(rows, fcl), g.ccd_vs_fcl, false, "", fmt::format("`{}` / `{}`", core, fcl)});
    out.push_back({fmt::format("ccd_{}_false_negatives", id), fmt::format("continuous test {}: core's false negatives on the mix", kind),
                   counter(rows, core, "false_negatives"), g.ccd_false_negatives, false, "",
                   fmt::format("`{}` counter `false_negatives` (against the exact referee)", core)});
    out.push_back({fmt::format("ccd_{}_false_positive_share", id),
                   fmt::format("continuous test {}: core's false positives / the referee's negatives", kind),
                   counter(rows, core, "false_positive_share"), g.ccd_false_positive_share, false, "",
                   fmt::format("`{}` counter `false_positive_share`", core)});
  }
}

/// Speed-up on 2 threads (wall time) and the same answer at every thread count.
void add_thread_goals(std::vector<GoalRow>& out, const std::vector<BenchRow>& rows, const Settings& s, const Goals& g) {
  for (const char* kind : {"", "discrete-"}) {
    const std::string one = fmt::format("BM_ContinuousSelfCollision/{}threads:1/{}", kind, s.threads_n);
    const std::string two = fmt::format("BM_ContinuousSelfCollision/{}threads:2/{}", kind, s.threads_n);
    out.push_back({fmt::format("threads_{}{}_speedup", kind[0] ? "discrete_" : "continuous_", s.threads_n),
                   fmt::format("{} detection {}x{}: speed-up on 2 threads, wall time", kind[0] ? "discrete" : "continuous", s.threads_n,
                               s.threads_n),
                   wall_ratio(rows, one, two), g.thread_speedup, true, "",
                   fmt::format("`{}` / `{}` (a row is missing when its answer differs from one thread's)", one, two)});
  }
  const int p = s.process_n;
  const std::string one = fmt::format("process/selfcollide/continuous/threads:1/{}", p);
  const std::string two = fmt::format("process/selfcollide/continuous/threads:2/{}", p);
  out.push_back({fmt::format("threads_selfcollide_process_{}_speedup", p),
                 fmt::format("whole `selfcollide --to` process {0}x{0}: speed-up on 2 threads, wall time", p), wall_ratio(rows, one, two),
                 g.thread_speedup, true, "", fmt::format("`{}` / `{}`", one, two)});
  double differ = NAN;
  for (const BenchRow& r : rows)
    if (r.counters.contains("same_answer")) differ = (std::isnan(differ) ? 0 : differ) + (r.counters["same_answer"] == 1 ? 0 : 1);
  out.push_back({"threads_answers_differing", "`selfcollide --to` outputs at 2 threads not byte-identical to one thread's (a count)",
                 differ, 0.0, false, "", "`process/selfcollide/continuous/threads:<t>/<n>` counter `same_answer`"});
}

/// Long runs: the kept detectors' time per step over detection from scratch.
void add_long_run_goals(std::vector<GoalRow>& out, const std::vector<BenchRow>& rows, const Goals& g) {
  for (const char* scene : {"experiment", "fold128"})
    for (const char* det : {"discrete", "continuous"}) {
      const std::string name = fmt::format("BM_SelfCollisionLongRun/{}/{}", scene, det);
      if (scene == std::string("fold128") && !find_row(rows, name)) continue;  // minutes of its own: only when run
      out.push_back({fmt::format("long_run_{}_{}_kept_over_scratch", scene, det), fmt::format("long run {}, {} detection: per-step time kept / from scratch", scene, det),
                     counter(rows, name, "reuse_us") / counter(rows, name, "scratch_us"), g.kept_over_scratch, false, "",
                     fmt::format("`{}` counters `reuse_us` / `scratch_us`", name)});
    }
}
}  // namespace

std::vector<GoalRow> goal_rows(const std::vector<BenchRow>& rows, const Settings& s, const Goals& g) {
  std::vector<GoalRow> out;
  add_core_goals(out, rows, s, g);
  add_continuous_goals(out, rows, s, g);
  add_ccd_goals(out, rows, g);
  add_thread_goals(out, rows, s, g);
  add_long_run_goals(out, rows, g);
  return out;
}

io::Json goals_json(const std::vector<GoalRow>& goals) {
  io::Json a = io::Json::array();
  for (const GoalRow& r : goals)
    a.push_back({{"id", r.id},
                 {"what", r.what},
                 {"value", r.measured() ? io::Json(r.value) : io::Json(nullptr)},
                 {"target", r.target},
                 {"comparison", r.at_least ? "at_least" : "at_most"},
                 {"unit", r.unit},
                 {"met", r.measured() ? io::Json(r.met()) : io::Json(nullptr)},
                 {"from", r.from}});
  return a;
}

}  // namespace tecido::suites::bench
