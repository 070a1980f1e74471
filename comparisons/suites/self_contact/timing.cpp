#include "comparisons/suites/self_contact/timing.h"

#include "comparisons/stats/stats.h"

#include "core/cloth/edge_response.h"
#include "core/cloth/mesh_topology.h"
#include "core/cloth/self_contact_counter.h"
#include "core/simulation/simulation.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace tecido::suites::self_contact {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

bool share_vertex(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  for (int u : a)
    for (int v : b)
      if (u == v) return true;
  return false;
}

/// Every pair of triangles sharing no vertex: the pairs the seed's O(n^2) loop tests.
std::vector<TrianglePair> all_pairs(const std::vector<std::array<int, 3>>& tris) {
  std::vector<TrianglePair> out;
  for (int i = 0; i < static_cast<int>(tris.size()); ++i)
    for (int j = i + 1; j < static_cast<int>(tris.size()); ++j)
      if (!share_vertex(tris[i], tris[j])) out.push_back({i, j});
  return out;
}

/// `count` frames' triangles, evenly spread over the run of `scene`.
std::vector<std::vector<Triangle>> record_frames(const Scene& scene, int count) {
  Simulation sim(scene);
  std::vector<std::vector<Triangle>> frames;
  const long long every = std::max(1LL, scene.steps / std::max(1, count));
  for (long long k = 1; k <= scene.steps && static_cast<int>(frames.size()) < count; ++k) {
    if (!sim.step()) break;
    if (k % every) continue;
    std::vector<Triangle> f;
    for (const auto& t : scene.triangles) f.push_back({sim.particles().x[t[0]], sim.particles().x[t[1]], sim.particles().x[t[2]]});
    frames.push_back(std::move(f));
  }
  return frames;
}

/// Nanoseconds per pair of `test` over every pair of every frame; adds its hits to `hits`.
double ns_per_pair(TriTriTest test, const std::vector<std::vector<Triangle>>& frames,
                   const std::vector<TrianglePair>& pairs, long long& hits) {
  long long h = 0;
  const auto t0 = Clock::now();
  for (const auto& f : frames)
    for (const TrianglePair& p : pairs) h += test(f[p[0]], f[p[1]]);
  const double s = seconds_since(t0);
  hits += h;
  return 1e9 * s / static_cast<double>(std::max<std::size_t>(1, frames.size() * pairs.size()));
}

}  // namespace

io::Json time_tri_tri(const Scene& scene, const Settings& s) {
  const auto frames = record_frames(scene, s.timing_frames);
  const auto pairs = all_pairs(scene.triangles);
  io::Json rot = io::Json::array(), mt = io::Json::array();
  long long h_rot = 0, h_mt = 0, h_exact = 0;
  for (int r = 0; r < s.timing_repeats; ++r) {
    long long scratch = 0;
    long long& hr = r == 0 ? h_rot : scratch;
    long long& hm = r == 0 ? h_mt : scratch;
    if (r % 2 == 0) {
      rot.push_back(ns_per_pair(contact_test_function(ContactTest::CoreRotation), frames, pairs, hr));
      mt.push_back(ns_per_pair(contact_test_function(ContactTest::CoreMt), frames, pairs, hm));
    } else {
      mt.push_back(ns_per_pair(contact_test_function(ContactTest::CoreMt), frames, pairs, hm));
      rot.push_back(ns_per_pair(contact_test_function(ContactTest::CoreRotation), frames, pairs, hr));
    }
  }
  ns_per_pair(contact_test_function(ContactTest::Core), frames, pairs, h_exact);
  return {{"kind", "tritri-timing"},
          {"frames", frames.size()},
          {"pairs", pairs.size()},
          {"ns_per_pair_rotation", rot},
          {"ns_per_pair_mt", mt},
          {"hits", {{"core", h_exact}, {"core-mt", h_mt}, {"core-rotation", h_rot}}}};
}

io::Json time_phases(const Scene& scene, const Settings& s) {
  Simulation sim(scene);  // no post_step: the phases are called and timed here
  const MeshTopology topo = build_mesh_topology(static_cast<int>(sim.particles().size()), scene.triangles);
  SelfCollisionDetector bvh(scene.triangles, sim.particles().x);
  std::vector<std::uint8_t> mark;
  const int per_block = std::max(1, s.phase_steps / std::max(1, s.phase_blocks));
  std::vector<double> t_step, t_brute, t_bvh, t_resp;
  long long found_brute = 0, found_bvh = 0;
  for (int b = 0; b < s.phase_blocks; ++b) {
    double step = 0, brute = 0, tree = 0, resp = 0;
    for (int k = 0; k < per_block; ++k) {
      auto t0 = Clock::now();
      if (!sim.step()) break;
      step += seconds_since(t0);
      Particles& p = sim.mutable_particles();
      t0 = Clock::now();
      const std::vector<TrianglePair> brute_pairs = self_collision_pairs_brute(p.x, scene.triangles, contact_test_function(ContactTest::CoreMt));
      brute += seconds_since(t0);
      found_brute += static_cast<long long>(brute_pairs.size());
      t0 = Clock::now();
      const auto& pairs = bvh.detect(p.x);
      tree += seconds_since(t0);
      found_bvh += static_cast<long long>(pairs.size());
      t0 = Clock::now();
      apply_edge_mode(EdgeMode::TowardMidpoint, topo, scene.triangles, pairs, nullptr, p.x, p.inv_mass,
                      scene.self_collision->strength, scene.dt, p.v, mark);
      resp += seconds_since(t0);
    }
    t_step.push_back(step / per_block);
    t_brute.push_back(brute / per_block);
    t_bvh.push_back(tree / per_block);
    t_resp.push_back(resp / per_block);
  }
  return {{"kind", "phase-timing"},
          {"steps_per_block", per_block},
          {"pairs_found", {{"detect_brute_mt", found_brute}, {"detect_bvh", found_bvh}}},
          {"seconds_per_step", {{"step", t_step}, {"detect_brute_mt", t_brute}, {"detect_bvh", t_bvh}, {"response", t_resp}}}};
}

namespace {

/// The threshold tests: above (support) and below (refute) `threshold`, one-sided t over the values.
void threshold_tests(Claim& c, const Summary& s, double threshold) {
  if (!take_summary(c, s)) return;
  c.p_support = stats::p_above(stats::mean_estimate(s), threshold);
  c.p_refute = stats::p_below(stats::mean_estimate(s), threshold);
}

const char* const kCostDecision =
    " Both p-values are Holm-adjusted over the three cost claims; reproduced if the adjusted support p < 0.05, else not "
    "reproduced if the adjusted refute p < 0.05, else inconclusive.";

std::vector<double> numbers(const io::Json& a) {
  std::vector<double> out;
  for (const auto& x : a) out.push_back(x.get<double>());
  return out;
}

Claim rotation_claim(const io::Json* tt, const Settings& s, const std::string& why) {
  Claim c;
  c.id = "rotation-slower-than-mt";
  c.family = "cost";
  c.wall_clock = true;
  c.unit = "ratio";
  c.statement = "The rotation test is much slower than Möller-Trumbore, even with the latter run both ways (section 3.1.3).";
  c.seed_text = "\"extremely low\" performance against \"much more efficient\"; no number";
  c.rule = fmt::format("threshold: per repetition, rotation ns per pair / Möller-Trumbore (both ways) ns per pair over "
                       "the same pairs (every pair sharing no vertex of frames of a no-response run); 95% t interval over "
                       "repetitions. \"Much\" read as at least {}x. Support: one-sided t test over repetitions that "
                       "the ratio lies above {}; refute: below.{}", s.much_slower, s.much_slower, kCostDecision);
  if (!tt) {
    c.reason = why;
    return c;
  }
  const auto rot = numbers(tt->at("ns_per_pair_rotation")), mt = numbers(tt->at("ns_per_pair_mt"));
  std::vector<double> ratio;
  for (std::size_t k = 0; k < rot.size() && k < mt.size(); ++k) ratio.push_back(rot[k] / mt[k]);
  const Summary r = summarize(ratio), sr = summarize(rot), sm = summarize(mt);
  threshold_tests(c, r, s.much_slower);
  c.observed_text = fmt::format("rotation {:.1f} ns, Möller-Trumbore both ways {:.1f} ns per pair, over {} pairs x {} "
                                "frames; pairs reported: exact {}, Möller-Trumbore {}, rotation {}",
                                sr.mean, sm.mean, tt->at("pairs").get<long long>(),
                                tt->at("frames").get<long long>(), tt->at("hits").at("core").get<long long>(),
                                tt->at("hits").at("core-mt").get<long long>(), tt->at("hits").at("core-rotation").get<long long>());
  return c;
}

Claim phase_claim(const io::Json* ph, const char* id, const char* detect_key, const std::string& how,
                  const std::string& why) {
  Claim c;
  c.id = id;
  c.family = "cost";
  c.wall_clock = true;
  c.unit = "ratio";
  c.statement = "Collision detection is the costliest part of a step (section 3.1.1; 3.1.3: \"the heaviest step of the "
                "whole process\"), " + how + ".";
  c.seed_text = "\"indubitably the costliest step\", O(n^2); no number";
  c.rule = std::string("threshold: per block of steps, detection time / the largest other phase (the step's forces and "
                       "integration, the edge response); 95% t interval over blocks. Support: one-sided t test that it "
                       "lies above 1; refute: below 1.") + kCostDecision;
  if (!ph) {
    c.reason = why;
    return c;
  }
  const io::Json& t = ph->at("seconds_per_step");
  const auto step = numbers(t.at("step")), det = numbers(t.at(detect_key)), resp = numbers(t.at("response"));
  std::vector<double> ratio, share;
  for (std::size_t b = 0; b < step.size(); ++b) {
    ratio.push_back(det[b] / std::max(step[b], resp[b]));
    share.push_back(det[b] / (step[b] + det[b] + resp[b]));
  }
  const Summary r = summarize(ratio), sh = summarize(share), ss = summarize(step), sd = summarize(det), sr = summarize(resp);
  threshold_tests(c, r, 1.0);
  c.observed_text = fmt::format("per step: forces and integration {:.1f} us, detection {:.1f} us, response {:.1f} us; "
                                "detection {:.0f}% of the step's time",
                                1e6 * ss.mean, 1e6 * sd.mean, 1e6 * sr.mean, 100.0 * sh.mean);
  return c;
}

}  // namespace

CostHalf detection_cost(const io::Json* phases, const Settings& s, const std::string& why) {
  CostHalf h;
  if (!phases) {
    h.reason = why;
    return h;
  }
  const io::Json& t = phases->at("seconds_per_step");
  const auto step = numbers(t.at("step")), det = numbers(t.at("detect_brute_mt")), resp = numbers(t.at("response"));
  std::vector<double> ratio;
  for (std::size_t b = 0; b < step.size(); ++b) ratio.push_back((step[b] + det[b] + resp[b]) / step[b]);
  Claim c;
  threshold_tests(c, summarize(ratio), s.much_slower);
  h.observed = c.observed;
  h.ci95 = c.ci95;
  h.n = c.n;
  h.p_support = c.p_support;
  h.p_refute = c.p_refute;
  h.reason = c.reason;
  return h;
}

std::vector<Claim> timing_claims(const io::Json* tritri, const io::Json* phases, const Settings& s,
                                 const std::string& why) {
  std::vector<Claim> out{rotation_claim(tritri, s, why),
          phase_claim(phases, "detection-dominates-step", "detect_brute_mt",
                      "with the seed's detection: every pair, Möller-Trumbore both ways", why),
          phase_claim(phases, "detection-dominates-step-bvh", "detect_bvh",
                      "with the harness's detection: a box tree and the exact test", why)};
  apply_holm(out, s.alpha);
  return out;
}

}  // namespace tecido::suites::self_contact
