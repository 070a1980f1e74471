#include "comparisons/suites/experiment_self_contact.h"

#include "comparisons/io/input_error.h"
#include "comparisons/io/progress.h"
#include "comparisons/io/scene_json.h"
#include "core/cloth/self_collision_response.h"
#include "core/dynamics/simulation.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>

namespace tecido::suites {

namespace {

constexpr double kWinds[3] = {0.09, 0.1, 0.11};
constexpr double kSteps[3] = {0.02, 0.01, 0.005};
constexpr double kElasticities[2] = {0.9, 0.5};
const char* const kResponses[4] = {"none", "edge1", "edge2", "edge3"};
const char* const kSeedColumns[4] = {"none", "mode1", "mode2", "mode3"};

/// Scales a JSON number (the document was validated by its reader or will be after patching).
void scale_number(io::Json& j, double f) {
  if (j.is_number()) j = j.get<double>() * f;
}

/// One-sided sign test: P(X >= k) for X ~ Binomial(n, 1/2).
double sign_test_p(int k, int n) {
  double p = 0.0;
  for (int i = k; i <= n; ++i) {
    double c = 1.0;
    for (int j = 0; j < i; ++j) c = c * (n - j) / (j + 1);
    p += c;
  }
  return p / std::pow(2.0, n);
}

}  // namespace

std::vector<SelfContactRun> self_contact_runs() {
  std::vector<SelfContactRun> runs;
  for (int w = 0; w < 3; ++w)
    for (int s = 0; s < 3; ++s)
      for (int e = 0; e < 2; ++e)
        for (int m = 0; m < 4; ++m) {
          SelfContactRun r;
          r.index = static_cast<int>(runs.size());
          r.wind = kWinds[w];
          r.dt = kSteps[s];
          r.elasticity = kElasticities[e];
          r.mode = m;
          runs.push_back(r);
        }
  return runs;
}

io::Json self_contact_scene(const io::Json& base, const SelfContactRun& run, const SelfContactOptions& opt,
                            const std::string& base_file) {
  io::Json doc = base;
  if (!doc.is_object()) throw io::InputError(base_file, "", "expected a scene object");
  doc["dt"] = run.dt;
  doc["steps"] = std::llround(opt.simulated_time / run.dt);
  if (!doc.contains("wind")) throw io::InputError(base_file, "/wind", "the experiment needs a wind to scale");
  io::Json& force = doc["wind"].is_object() ? doc["wind"]["force"] : doc["wind"];
  if (!force.is_array() || force.size() != 3) throw io::InputError(base_file, "/wind", "expected a force [fx,fy,fz]");
  double norm = 0.0;
  for (const auto& c : force) norm += c.is_number() ? c.get<double>() * c.get<double>() : 0.0;
  norm = std::sqrt(norm);
  if (!(norm > 0.0)) throw io::InputError(base_file, "/wind", "the wind force must not be zero (its direction is kept)");
  for (auto& c : force) scale_number(c, run.wind / norm);
  if (!doc.contains("cloth") || !doc["cloth"].is_object())
    throw io::InputError(base_file, "/cloth", "the experiment needs a cloth");
  io::Json& cloth = doc["cloth"];
  if (opt.elasticity_as == "stiffness") {
    if (cloth.contains("stiffness_b")) scale_number(cloth["stiffness_b"], run.elasticity);
    if (cloth.contains("stiffness_a")) scale_number(cloth["stiffness_a"], run.elasticity);
  } else if (opt.elasticity_as == "restitution") {
    cloth["elasticity"] = run.elasticity;
  } else {
    throw io::UsageError("--elasticity-as must be stiffness or restitution");
  }
  if (!doc.contains("self_collision") || !doc["self_collision"].is_object())
    throw io::InputError(base_file, "/self_collision", "the experiment needs self_collision (its strength)");
  doc["self_collision"]["response"] = kResponses[run.mode];
  if (opt.strength >= 0.0) doc["self_collision"]["strength"] = opt.strength;
  return doc;
}

SelfContactResult run_self_contact(const io::Json& base, const SelfContactRun& run, const SelfContactOptions& opt) {
  const Scene scene = io::scene_from_json(self_contact_scene(base, run, opt, opt.scene_path), opt.scene_path);
  Simulation sim(scene);
  const auto responder = install_self_collision(sim);
  sim.run(scene.steps);
  SelfContactResult r;
  r.run = run;
  const SelfCollisionStats& st = responder->stats();
  r.frames = st.checks;
  r.contact_frames = st.contact_checks;
  r.share = r.frames > 0 ? static_cast<double>(r.contact_frames) / static_cast<double>(r.frames) : 0.0;
  r.pairs = st.pairs;
  r.max_pairs = st.max_pairs;
  if (sim.instability()) {
    r.status = "unstable";
    r.unstable_at_step = sim.instability()->step;
  }
  return r;
}

std::vector<int> self_contact_selection(const SelfContactOptions& opt) {
  const int count = static_cast<int>(self_contact_runs().size());
  std::vector<int> out;
  if (opt.runs.empty()) {
    for (int i = 0; i < count; ++i) out.push_back(i);
    return out;
  }
  for (int i : opt.runs) {
    if (i < 0 || i >= count) throw io::UsageError("--runs: run index " + std::to_string(i) + " is outside 0..71");
    out.push_back(i);
  }
  return out;
}

std::vector<SelfContactResult> run_self_contact_experiment(const SelfContactOptions& opt) {
  if (opt.shard_count < 1 || opt.shard_index < 0 || opt.shard_index >= opt.shard_count)
    throw io::UsageError("--shard: expected i/n with 0 <= i < n");
  const io::Json base = io::read_json_file(opt.scene_path);
  // Validate the base scene once, on the calling thread, so bad input is reported plainly.
  {
    const Scene s = io::scene_from_json(base, opt.scene_path);
    if (!s.self_collision) throw io::InputError(opt.scene_path, "/self_collision", "the experiment needs self_collision");
  }
  std::vector<SelfContactRun> runs;
  const auto all = self_contact_runs();
  for (int i : self_contact_selection(opt))
    if (i % opt.shard_count == opt.shard_index) runs.push_back(all[i]);
  std::unique_ptr<io::Progress> progress;
  if (opt.progress) progress = std::make_unique<io::Progress>(runs.size(), "self-contact");
  std::vector<SelfContactResult> results(runs.size());
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto worker = [&]() {
    for (;;) {
      const std::size_t k = next.fetch_add(1);
      if (k >= runs.size()) return;
      try {
        results[k] = run_self_contact(base, runs[k], opt);
        if (progress) progress->tick();
      } catch (...) {
        std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
      }
    }
  };
  const int n = std::max(1, std::min<int>(opt.threads, static_cast<int>(runs.size())));
  std::vector<std::thread> pool;
  for (int t = 1; t < n; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (progress) progress->finish();
  if (error) std::rethrow_exception(error);
  return results;
}

namespace {

nlohmann::ordered_json self_contact_document(const std::vector<SelfContactResult>& results, const SelfContactOptions& opt,
                                             nlohmann::ordered_json out) {
  nlohmann::ordered_json runs = nlohmann::ordered_json::array();
  for (const auto& r : results) {
    nlohmann::ordered_json j;
    j["index"] = r.run.index;
    j["elasticity"] = r.run.elasticity;
    j["dt"] = r.run.dt;
    j["wind"] = r.run.wind;
    j["mode"] = r.run.mode == 0 ? nlohmann::ordered_json("none") : nlohmann::ordered_json(r.run.mode);
    j["frames"] = r.frames;
    j["contact_frames"] = r.contact_frames;
    j["share"] = r.share;
    j["status"] = r.status;
    j["unstable_at_step"] = r.unstable_at_step >= 0 ? nlohmann::ordered_json(r.unstable_at_step) : nullptr;
    j["pairs"] = r.pairs;
    j["max_pairs"] = r.max_pairs;
    runs.push_back(std::move(j));
  }
  out["experiment"] = "self-contact";
  out["scene"] = opt.scene_path;
  out["simulated_time"] = opt.simulated_time;
  out["quick"] = opt.quick;
  out["elasticity_as"] = opt.elasticity_as;
  out["strength"] = opt.strength >= 0.0 ? nlohmann::ordered_json(opt.strength) : nlohmann::ordered_json("scene");
  out["runs"] = std::move(runs);
  return out;
}

}  // namespace

std::string self_contact_json(const std::vector<SelfContactResult>& results, const SelfContactOptions& opt) {
  return self_contact_document(results, opt, nlohmann::ordered_json::object()).dump(2) + "\n";
}

std::string self_contact_shard_json(const std::vector<SelfContactResult>& results, const SelfContactOptions& opt) {
  nlohmann::ordered_json head;
  head["shard"] = {opt.shard_index, opt.shard_count};
  head["selection"] = self_contact_selection(opt);
  head["seed_table"] = opt.seed_table_path;
  return self_contact_document(results, opt, std::move(head)).dump(2) + "\n";
}

namespace {

/// The seed's share for (wind, steps per second, elasticity, column), or NaN when absent.
double seed_share(const io::Json& seed, double wind, int sps, double e, int mode) {
  if (!seed.is_object() || !seed.contains("tables")) return std::nan("");
  for (const auto& t : seed["tables"]) {
    if (!t.contains("wind") || std::abs(t["wind"].get<double>() - wind) > 1e-9) continue;
    for (const auto& row : t["rows"]) {
      if (row["steps_per_second"].get<int>() != sps || std::abs(row["elasticity"].get<double>() - e) > 1e-9) continue;
      if (row.contains(kSeedColumns[mode])) return row[kSeedColumns[mode]].get<double>();
    }
  }
  return std::nan("");
}

struct Tally {
  int better = 0, worse = 0, cells = 0;
  double rel_sum = 0.0;  // sum of (mode - none) / none
};

}  // namespace

std::string self_contact_markdown(const std::vector<SelfContactResult>& results, const io::Json& seed_tables,
                                  const SelfContactOptions& opt) {
  // Index results by (wind, step, elasticity, mode).
  const SelfContactResult* cell[3][3][2][4] = {};
  for (const auto& r : results) {
    const int i = r.run.index;
    cell[i / 24][(i / 8) % 3][(i / 4) % 2][i % 4] = &r;
  }
  std::string md;
  md += "# Self-contact experiment (seed section 3.1.3, fig. 21, tables 1-3)\n\n";
  md += fmt::format("Scene `{}`; {} s simulated per run{}; elasticity read as **{}**; response strength {}. ",
                    opt.scene_path, opt.simulated_time,
                    opt.quick ? " (**--quick**: not comparable with the seed's 10 s)" : "", opt.elasticity_as,
                    opt.strength >= 0.0 ? fmt::format("{} N (--strength)", opt.strength) : std::string("as in the scene"));
  md += "Each cell is the share of frames (steps) after which at least one pair of triangles sharing no vertex "
        "intersects: **ours / the seed's**. Columns: no response, the seed's edge modes 1, 2, 3.\n\n";

  Tally ours[4], seeds[4];
  double wind_rel_ours[3] = {0, 0, 0}, wind_rel_seed[3] = {0, 0, 0};
  int wind_cells[3] = {0, 0, 0};
  for (int w = 0; w < 3; ++w) {
    md += fmt::format("## Table {}: wind {} N\n\n", w + 1, kWinds[w]);
    md += "| steps per second | elasticity | none | mode 1 | mode 2 | mode 3 |\n|---|---|---|---|---|---|\n";
    for (int s = 0; s < 3; ++s) {
      const int sps = static_cast<int>(std::lround(1.0 / kSteps[s]));
      for (int e = 0; e < 2; ++e) {
        md += fmt::format("| {} | {} |", sps, kElasticities[e]);
        const SelfContactResult* none = cell[w][s][e][0];
        const double seed_none = seed_share(seed_tables, kWinds[w], sps, kElasticities[e], 0);
        for (int m = 0; m < 4; ++m) {
          const SelfContactResult* r = cell[w][s][e][m];
          const double sd = seed_share(seed_tables, kWinds[w], sps, kElasticities[e], m);
          std::string ours_s = r ? fmt::format("{:.4f}", r->share) : "-";
          if (r && r->status != "ok") ours_s += " (unstable)";
          md += fmt::format(" {} / {} |", ours_s, std::isnan(sd) ? std::string("-") : fmt::format("{:.5g}", sd));
          if (m == 0) continue;
          if (r && none) {
            ++ours[m].cells;
            if (r->share < none->share) ++ours[m].better;
            if (r->share > none->share) ++ours[m].worse;
            if (none->share > 0) ours[m].rel_sum += (r->share - none->share) / none->share;
            if (m == 3 && none->share > 0) {
              wind_rel_ours[w] += (r->share - none->share) / none->share;
            }
          }
          if (!std::isnan(sd) && !std::isnan(seed_none)) {
            ++seeds[m].cells;
            if (sd < seed_none) ++seeds[m].better;
            if (sd > seed_none) ++seeds[m].worse;
            seeds[m].rel_sum += (sd - seed_none) / seed_none;
            if (m == 3) wind_rel_seed[w] += (sd - seed_none) / seed_none;
          }
        }
        if (cell[w][s][e][3] && cell[w][s][e][0]) ++wind_cells[w];
        md += "\n";
      }
    }
    md += "\n";
  }

  md += "## Against the no-response column\n\n";
  md += "| response | lower than none (ours) | higher (ours) | mean relative change (ours) | lower (seed) | higher (seed) | mean "
        "relative change (seed) |\n|---|---|---|---|---|---|---|\n";
  for (int m = 1; m < 4; ++m) {
    md += fmt::format("| mode {} | {} of {} | {} | {:+.1f}% | {} of {} | {} | {:+.1f}% |\n", m, ours[m].better, ours[m].cells,
                      ours[m].worse, ours[m].cells ? 100.0 * ours[m].rel_sum / ours[m].cells : 0.0, seeds[m].better,
                      seeds[m].cells, seeds[m].worse, seeds[m].cells ? 100.0 * seeds[m].rel_sum / seeds[m].cells : 0.0);
  }
  md += "\nMode 3's mean relative change per wind (the seed: about -10% at 0.1 N, about -20% at the others):";
  for (int w = 0; w < 3; ++w) {
    md += fmt::format(" {} N: ours {}, seed {:+.1f}%;", kWinds[w],
                      wind_cells[w] ? fmt::format("{:+.1f}%", 100.0 * wind_rel_ours[w] / wind_cells[w]) : std::string("-"),
                      100.0 * wind_rel_seed[w] / 6.0);
  }
  md += "\n\n";

  md += "## Do the seed's conclusions hold here?\n\n";
  const int n3 = ours[3].cells, n2 = ours[2].cells;
  if (n3 == 0) {
    md += "Not enough runs to judge (the none and mode columns of a cell are both needed).\n";
    return md;
  }
  const bool a_holds = 2 * ours[3].better > n3;
  md += fmt::format(
      "(a) *Mode 3 lowers the share of frames with self-contact compared with no response in most cells* (the seed: "
      "{} of {}; one-sided sign test p = {:.2g}). Here: {} of {} (p = {:.2g}). **{}**.\n\n",
      seeds[3].better, seeds[3].cells, sign_test_p(seeds[3].better, seeds[3].cells), ours[3].better, n3,
      sign_test_p(ours[3].better, n3), a_holds ? "Holds" : "Does not hold");
  const bool b_holds = n2 > 0 && 2 * ours[2].better <= n2;
  md += fmt::format(
      "(b) *Mode 2 does not help* (the seed: higher than none in {} of {}, lower in {}). Here: higher in {} of {}, lower "
      "in {} (mean relative change {:+.1f}%). **{}**.\n\n",
      seeds[2].worse, seeds[2].cells, seeds[2].better, ours[2].worse, n2, ours[2].better,
      n2 ? 100.0 * ours[2].rel_sum / n2 : 0.0, b_holds ? "Holds" : "Does not hold");
  // How much a cell moves with the step: converged runs make the columns' differences
  // systematic; chaotic ones make each cell one noisy sample.
  double max_spread = 0.0, sum_spread = 0.0, seed_max = 0.0, seed_sum = 0.0;
  int groups = 0, seed_groups = 0;
  for (int w = 0; w < 3; ++w)
    for (int e = 0; e < 2; ++e)
      for (int m = 0; m < 4; ++m) {
        double lo = 2, hi = -1, slo = 2, shi = -1;
        bool all = true;
        for (int st = 0; st < 3; ++st) {
          const SelfContactResult* r = cell[w][st][e][m];
          all = all && r;
          if (r) {
            lo = std::min(lo, r->share);
            hi = std::max(hi, r->share);
          }
          const double sd = seed_share(seed_tables, kWinds[w], static_cast<int>(std::lround(1.0 / kSteps[st])),
                                       kElasticities[e], m);
          if (!std::isnan(sd)) {
            slo = std::min(slo, sd);
            shi = std::max(shi, sd);
          }
        }
        if (all) {
          max_spread = std::max(max_spread, hi - lo);
          sum_spread += hi - lo;
          ++groups;
        }
        if (shi >= 0) {
          seed_max = std::max(seed_max, shi - slo);
          seed_sum += shi - slo;
          ++seed_groups;
        }
      }
  if (groups > 0) {
    md += fmt::format(
        "How much a cell depends on the step: over the three steps, the share of one (wind, elasticity, response) "
        "varies by {:.3f} on average and {:.3f} at most here; in the seed's tables by {:.3f} on average and {:.3f} at "
        "most. ",
        sum_spread / groups, max_spread, seed_groups ? seed_sum / seed_groups : 0.0, seed_max);
    if (max_spread < 0.05) {
      md += "Our runs converge as the step shrinks: a cell is not a noisy sample, and the differences between columns "
            "are systematic effects of the response. ";
    } else {
      md += "Our runs do not converge with the step (the cloth in a circling wind behaves chaotically), so one cell "
            "compares two samples of a noisy process. ";
    }
  }
  md += "The sign test asks how likely the count of cells where a mode beats no response would be if the mode did "
        "nothing (each cell a coin toss); it ignores the correlation between the cells of one table.\n";
  return md;
}

}  // namespace tecido::suites
