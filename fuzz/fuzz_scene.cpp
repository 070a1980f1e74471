// libFuzzer target: bytes -> io::parse_json_text -> io::scene_from_json (the path of every
// `tecido run SCENE`). Rejections must be io::InputError. A scene the reader accepts must keep
// its promises (indices in range, finite state, positive step, sizes within the limits of
// comparisons/io/limits.h, nesting within io::kMaxJsonDepth) and, when small, must survive a
// few simulation steps with its self-collision hook, as `tecido run` would run it: a state
// that stops being finite is reported as "unstable", never a crash.
#include "fuzz_common.h"

#include "comparisons/io/limits.h"
#include "comparisons/io/run_result.h"
#include "comparisons/io/scene_json.h"
#include "core/simulation/self_collision_response.h"
#include "core/simulation/simulation.h"

#include <algorithm>
#include <cmath>

namespace {

constexpr const char* kTarget = "fuzz_scene";

void check_invariants(const tecido::Scene& s) {
  using tecido::fuzz::finding;
  const auto n = static_cast<long long>(s.particles.size());
  if (n == 0) finding(kTarget, "accepted a scene without particles");
  if (!(s.dt > 0.0) || !std::isfinite(s.dt)) finding(kTarget, "accepted dt " + std::to_string(s.dt));
  if (s.steps < 0) finding(kTarget, "accepted negative steps");
  const auto& p = s.particles;
  if (p.v.size() != p.x.size() || p.inv_mass.size() != p.x.size() || p.elasticity.size() != p.x.size() ||
      p.pinned.size() != p.x.size())
    finding(kTarget, "particle arrays of different lengths");
  for (long long i = 0; i < n; ++i) {
    if (!p.x[i].allFinite() || !p.v[i].allFinite()) finding(kTarget, "accepted a non-finite state, particle " + std::to_string(i));
    if (!(p.inv_mass[i] >= 0.0) || !std::isfinite(p.inv_mass[i]))
      finding(kTarget, "inverse mass not finite and >= 0, particle " + std::to_string(i));
    if (!(p.elasticity[i] >= 0.0 && p.elasticity[i] <= 1.0)) finding(kTarget, "elasticity outside [0,1]");
  }
  for (const auto& sp : s.forces.springs) {
    if (sp.i < 0 || sp.j < 0 || sp.i >= n || sp.j >= n || sp.i == sp.j) finding(kTarget, "accepted a spring with bad ends");
    if (!(sp.stiffness >= 0.0) || !(sp.rest_length >= 0.0) || !(sp.damping >= 0.0) || !std::isfinite(sp.stiffness) ||
        !std::isfinite(sp.rest_length) || !std::isfinite(sp.damping))
      finding(kTarget, "accepted a spring with a negative or non-finite parameter");
  }
  for (const auto& t : s.triangles)
    for (int k : t)
      if (k < 0 || k >= n) finding(kTarget, "triangle index out of range");
  if (s.particles.size() > tecido::io::kMaxParticles || s.forces.springs.size() > tecido::io::kMaxSprings ||
      s.planes.size() > tecido::io::kMaxPlanes || s.triangles.size() > tecido::io::kMaxTriangles)
    finding(kTarget, "accepted a scene past the limits of comparisons/io/limits.h");
  for (const auto& pl : s.planes)
    if (!pl.position.allFinite() || !pl.normal.allFinite() || !pl.forward.allFinite() || !pl.half_extents.allFinite())
      finding(kTarget, "accepted a non-finite plane");
}

/// A cloth of more than 2^16 nodes that the reader would accept and build.
bool large_cloth(const tecido::io::Json& doc) {
  if (!doc.is_object() || !doc.contains("cloth") || !doc["cloth"].is_object()) return false;
  const auto& c = doc["cloth"];
  if (!c.contains("rows") || !c.contains("cols") || !c["rows"].is_number() || !c["cols"].is_number()) return false;
  const double rows = c["rows"].get<double>(), cols = c["cols"].get<double>();
  return rows * cols > 65536.0 && rows * cols <= static_cast<double>(tecido::io::kMaxClothNodes) &&
         rows <= tecido::io::kMaxClothSide && cols <= tecido::io::kMaxClothSide;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = tecido::fuzz::as_text(data, size);
  tecido::fuzz::expect_only_input_errors(kTarget, [&] {
    const tecido::io::Json doc = tecido::fuzz::parse_checked(kTarget, text);
    // A cloth is as large as it says (the memory of the scene it describes, up to the limit of
    // 2^20 nodes, is legitimate): large ones are not built here, so that -rss_limit_mb measures
    // the reader, not the scene. Sides past the limit still go to the reader, which rejects them.
    if (large_cloth(doc)) return;
    const tecido::Scene scene = tecido::io::scene_from_json(doc, "fuzz.json");
    check_invariants(scene);
    // Simulate a few steps of small scenes (big ones would only measure the allocator).
    if (scene.particles.size() > 512 || scene.forces.springs.size() > 8192) return;
    tecido::Simulation sim(scene);
    const auto hook = tecido::install_self_collision(sim);
    sim.run(std::min<long long>(scene.steps, 3));
    const std::string out = tecido::io::run_result_json(sim).dump();
    if (out.empty()) tecido::fuzz::finding(kTarget, "empty result");
  });
  return 0;
}
