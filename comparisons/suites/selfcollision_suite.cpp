#include "comparisons/suites/selfcollision_suite.h"

#include "comparisons/engines/self_collision_engines.h"
#include "comparisons/io/scene_json.h"
#include "core/cloth/cloth_builder.h"
#include "core/cloth/self_collision.h"
#include "core/dynamics/simulation.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

namespace tecido::suites {

void PairAgreement::add(const std::vector<std::array<int, 2>>& got, const std::vector<std::array<int, 2>>& truth) {
  std::vector<std::array<int, 2>> common;
  std::set_intersection(got.begin(), got.end(), truth.begin(), truth.end(), std::back_inserter(common));
  reported += static_cast<long>(got.size());
  true_positives += static_cast<long>(common.size());
  false_positives += static_cast<long>(got.size() - common.size());
  missed += static_cast<long>(truth.size() - common.size());
}

namespace {

struct Frame {
  std::string source;
  double time;
  std::vector<Vec3> x;
  const std::vector<std::array<int, 3>>* triangles;
};

/// Records `count` frames, one every `every` steps, keeping frames that have at least one
/// intersecting pair (by core) first, so the comparison is about contacts, plus a few without.
void record(const Scene& s, const std::string& name, long long steps, long long every, int count,
            std::vector<Frame>& out, const std::vector<std::array<int, 3>>& tris) {
  Simulation sim(s);
  SelfCollisionDetector det(tris, s.particles.x);
  int with = 0, without = 0;
  for (long long i = 1; i <= steps && with + without < count; ++i) {
    if (!sim.step()) break;
    if (i % every) continue;
    const bool contact = !det.detect(sim.particles().x).empty();
    if (contact ? with < count * 3 / 4 : without < count / 4) {
      (contact ? with : without)++;
      out.push_back(Frame{name, sim.time(), sim.particles().x, &tris});
    }
  }
}

}  // namespace

SuiteResult run_selfcollision_suite(const SuiteContext& ctx) {
  SuiteResult res;
  res.name = "selfcollision";
  const Tolerances& tol = *ctx.tolerances;
  const int frames_per_source = ctx.quick ? 4 : 12;

  // Source 1: the seed's experiment scene (fig. 21), no self-collision response.
  Scene seed_scene = io::load_scene(ctx.data_dir + "/scenes/seed_fig21_self_contact.json");
  seed_scene.self_collision.reset();
  // Source 2: a soft cloth dropped onto a floor, crumpling into itself.
  Scene crumple;
  crumple.dt = 0.002;
  crumple.forces.gravity = Vec3(0, 0, -9.81);
  crumple.forces.air_drag = 0.002;
  {
    ClothGridSpec g;
    g.rows = g.cols = ctx.quick ? 16 : 24;
    g.spacing = 0.05;
    g.origin = Vec3(-0.4, -0.4, 0.6);
    g.axis_u = Vec3(1, 0, 0);
    g.axis_v = Vec3(0, 0.8, 0.6);
    g.total_mass = 0.3;
    g.stiffness_b = 20.0;
    g.elasticity = 0.1;
    append_cloth(crumple, g);
    for (auto& k : crumple.particles.elasticity) k = 0.1;
  }
  crumple.planes.push_back(make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), Vec2(3, 3), 0.9));
  std::vector<Frame> frames;
  const auto seed_tris = seed_scene.triangles;
  const auto crumple_tris = crumple.triangles;
  record(seed_scene, "seed-fig21", static_cast<long long>(10.0 / seed_scene.dt), std::max(1LL, static_cast<long long>(0.05 / seed_scene.dt)),
         frames_per_source, frames, seed_tris);
  record(crumple, "crumple", 1500, 25, frames_per_source, frames, crumple_tris);

  const SelfCollisionEngine* truth_engine = find_self_collision_engine("exact");
  if (!truth_engine) truth_engine = find_self_collision_engine("core-brute");
  std::string md = fmt::format(
      "{} frames: up to {} from the seed's experiment scene (fig. 21, no response; {} triangles) and up to {} from a soft "
      "cloth crumpling onto a floor ({} triangles), three quarters of them with contacts. Truth: `{}`. Precision = "
      "reported pairs that are true / reported; recall = true pairs reported / true pairs (1 when both are empty).\n\n",
      frames.size(), frames_per_source, seed_tris.size(), frames_per_source, crumple_tris.size(), truth_engine->name);
  std::vector<std::vector<TrianglePair>> truth;
  for (const Frame& f : frames) truth.push_back(truth_engine->pairs(f.x, *f.triangles).value_or(std::vector<TrianglePair>{}));
  std::size_t true_total = 0;
  for (const auto& t : truth) true_total += t.size();
  md += fmt::format("True intersecting pairs over all frames: {}.\n\n", true_total);
  md += "| engine | source | frames | reported | true positives | false positives | missed | precision | recall | ms per frame |\n"
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  io::Json data = io::Json::object();
  for (const auto& eng : self_collision_engines()) {
    for (const std::string src : {"seed-fig21", "crumple"}) {
      PairAgreement agg;
      long n = 0, unanswered = 0;
      double secs = 0.0;
      for (std::size_t i = 0; i < frames.size(); ++i) {
        if (frames[i].source != src) continue;
        ++n;
        const auto t0 = std::chrono::steady_clock::now();
        const auto got = eng.pairs(frames[i].x, *frames[i].triangles);
        secs += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (!got) {
          ++unanswered;
          continue;
        }
        agg.add(*got, truth[i]);
      }
      const double precision = agg.precision(), recall = agg.recall();
      const long reported = agg.reported, tp = agg.true_positives, fp = agg.false_positives, missed = agg.missed;
      md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {:.4f} | {:.4f} | {:.2f} |{}\n", eng.name, src, n, reported, tp, fp,
                        missed, precision, recall, n ? 1e3 * secs / n : 0.0,
                        unanswered ? fmt::format(" {} frames unanswered", unanswered) : "");
      data[eng.name][src] = {{"frames", n}, {"reported", reported}, {"true_positives", tp}, {"false_positives", fp},
                             {"missed", missed}, {"precision", precision}, {"recall", recall}};
      if (eng.name == truth_engine->name) continue;
      const std::string key = "/selfcollision/" + eng.name + "_min";
      const double lo = tol.get(key);
      res.checks.push_back(make_check(fmt::format("selfcollision/{}/{}/precision", eng.name, src), precision, lo, 1.0));
      res.checks.push_back(make_check(fmt::format("selfcollision/{}/{}/recall", eng.name, src), recall, lo, 1.0));
    }
  }
  md += "\n`core` (box tree + exact narrow phase) must match the exact referee pair for pair (precision and recall 1). "
        "FCL's BVH returns every adjacent pair of a mesh against itself; its pairs are filtered to those sharing no "
        "vertex, and its leaf test is FCL's own floating-point triangle test.\n";
  res.markdown = md;
  res.data = data;
  return res;
}

}  // namespace tecido::suites
