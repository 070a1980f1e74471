#include "comparisons/suites/ccd/sheet_through_sheet.h"

#include "core/scene/cloth_builder.h"
#include "core/cloth/continuous_self_collision.h"
#include "core/cloth/self_collision.h"
#include "core/simulation/self_collision_response.h"
#include "core/simulation/simulation.h"
#include "reference/exact_ccd.h"
#include "reference/exact_referee.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

namespace tecido::suites::ccd {

namespace {

constexpr double kSide = 1.0;   ///< each sheet's side [m]
constexpr double kGap = 0.04;   ///< B's height above A at the first frame, and below it at the second [m]

ClothGridSpec sheet(int n, const Vec3& origin, const Vec3& u, const Vec3& v) {
  ClothGridSpec c;
  c.rows = c.cols = n;
  c.spacing = kSide / (n - 1);
  c.origin = origin;
  c.axis_u = u.normalized();
  c.axis_v = v.normalized();
  // Soft and heavy enough for the step: a corner node (1/6 of a node's share of the mass) on its
  // springs keeps omega dt well below symplectic Euler's limit of 2 (about 0.5 at n = 12).
  c.total_mass = 1.0;
  c.stiffness_b = 1.0;
  return c;
}

/// Pairs in exactly one of two sorted lists.
template <class T>
long symmetric_difference(const std::vector<T>& a, const std::vector<T>& b) {
  std::vector<T> d;
  std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(d));
  return static_cast<long>(d.size());
}

/// Pairs of `truth` missing from `got` (both sorted).
template <class T>
long missing(const std::vector<T>& truth, const std::vector<T>& got) {
  std::vector<T> d;
  std::set_difference(truth.begin(), truth.end(), got.begin(), got.end(), std::back_inserter(d));
  return static_cast<long>(d.size());
}

}  // namespace

SheetScene sheet_through_sheet_scene(const SheetSettings& s) {
  SheetScene out;
  Scene& sc = out.scene;
  sc.dt = s.dt;
  sc.steps = s.steps;
  append_cloth(sc, sheet(s.n, Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)));
  out.first_b = static_cast<int>(sc.particles.size());
  // B: turned by 0.3 rad, centred over A, tilted by 0.01 (its height varies by under 0.015 m < kGap).
  const double a = 0.3;
  const Vec3 u(std::cos(a), std::sin(a), 0.01), v(-std::sin(a), std::cos(a), 0.005);
  const Vec3 centre(0.5 * kSide, 0.5 * kSide, kGap);
  const Vec3 origin = centre - 0.5 * kSide * (u.normalized() + v.normalized());
  append_cloth(sc, sheet(s.n, origin, u, v));
  out.x0 = sc.particles.x;
  out.x1 = out.x0;
  for (std::size_t i = static_cast<std::size_t>(out.first_b); i < out.x1.size(); ++i) {
    out.x1[i] += Vec3(0, 0, -2.0 * kGap);
    sc.particles.v[i] = (out.x1[i] - out.x0[i]) / s.dt;
  }
  return out;
}

namespace {

CcdAnswer exact_test(const CcdQuery& q) { return reference::to_ccd_answer(reference::exact_ccd(q)); }

/// The referee's contacts between two frames.
ContinuousContacts exact_contacts(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                                  const std::vector<std::array<int, 3>>& tris) {
  return continuous_self_collision_brute(x0, x1, tris, &exact_test);
}

/// The two frames: discrete detection in each, and the continuous engines against the referee.
void frames(const SheetScene& sc, SheetResult& r) {
  const auto& tris = sc.scene.triangles;
  for (const auto* x : {&sc.x0, &sc.x1}) {
    SelfCollisionDetector det(tris, sc.x0);
    r.discrete_pairs += static_cast<long>(det.detect(*x).size());
    r.discrete_pairs += static_cast<long>(self_collision_pairs_brute(*x, tris, &reference::exact_tri_tri).size());
  }
  const ContinuousContacts truth = exact_contacts(sc.x0, sc.x1, tris);
  ContinuousSelfCollisionDetector det(tris, sc.x0);
  const ContinuousContacts candidates = det.detect(sc.x0, sc.x1);
  const ContinuousContacts core = filter_contacts(candidates, sc.x0, sc.x1, tris,
                                                  [](const CcdQuery& q) { return reference::exact_ccd(q).hit; });
  const ContinuousContacts brute = continuous_self_collision_brute(sc.x0, sc.x1, tris);
  r.exact_contacts = static_cast<long>(truth.vertex_face.size() + truth.edge_edge.size());
  r.core_contacts = static_cast<long>(core.vertex_face.size() + core.edge_edge.size());
  r.core_missed = missing(truth.vertex_face, core.vertex_face) + missing(truth.edge_edge, core.edge_edge);
  r.core_extra = missing(core.vertex_face, truth.vertex_face) + missing(core.edge_edge, truth.edge_edge);
  r.candidates_differ = symmetric_difference(candidates.vertex_face, brute.vertex_face) +
                        symmetric_difference(candidates.edge_edge, brute.edge_edge);
  r.brute_missed = missing(truth.vertex_face, brute.vertex_face) + missing(truth.edge_edge, brute.edge_edge);
}

/// Mean height of B's particles minus A's at the end of a run.
double b_over_a(const Simulation& sim, int first_b) {
  const auto& x = sim.particles().x;
  double a = 0.0, b = 0.0;
  for (int i = 0; i < static_cast<int>(x.size()); ++i) (i < first_b ? a : b) += x[i].z();
  return b / (static_cast<int>(x.size()) - first_b) - a / first_b;
}

/// The two runs from the first frame (SheetResult's last three fields).
void runs(const SheetSettings& s, const SheetScene& sc, SheetResult& r) {
  Scene none = sc.scene;
  none.self_collision = SelfCollisionSettings{};
  Simulation plain(none);
  const auto seen = install_self_collision(plain);
  plain.run(s.steps);
  r.discrete_passed = b_over_a(plain, sc.first_b) < 0.0 ? 1 : 0;
  r.discrete_run_contacts = seen->stats().contact_checks;

  Scene impulse = sc.scene;
  impulse.self_collision = SelfCollisionSettings{};
  impulse.self_collision->detection = SelfCollisionDetection::Continuous;
  impulse.self_collision->response = SelfCollisionResponse::Impulse;
  Simulation sim(impulse);
  install_self_collision(sim);
  for (int k = 0; k < s.steps; ++k) {
    const std::vector<Vec3> before = sim.particles().x;
    if (!sim.step()) break;
    const ContinuousContacts c = exact_contacts(before, sim.particles().x, impulse.triangles);
    r.impulse_contacts += static_cast<long>(c.vertex_face.size() + c.edge_edge.size());
    ++r.impulse_steps;
  }
}

}  // namespace

SheetResult run_sheet_through_sheet(const SheetSettings& s) {
  const SheetScene sc = sheet_through_sheet_scene(s);
  SheetResult r;
  frames(sc, r);
  runs(s, sc, r);
  return r;
}

io::Json sheet_result_json(const SheetResult& r) {
  return {{"discrete_pairs", r.discrete_pairs},   {"exact_contacts", r.exact_contacts},
          {"core_contacts", r.core_contacts},     {"core_missed", r.core_missed},
          {"core_extra", r.core_extra},           {"candidates_differ", r.candidates_differ},
          {"brute_missed", r.brute_missed},       {"discrete_passed", r.discrete_passed},
          {"discrete_run_contacts", r.discrete_run_contacts},
          {"impulse_contacts", r.impulse_contacts}, {"impulse_steps", r.impulse_steps}};
}

SheetResult sheet_result_from_json(const io::Json& j) {
  SheetResult r;
  r.discrete_pairs = j.at("discrete_pairs").get<long>();
  r.exact_contacts = j.at("exact_contacts").get<long>();
  r.core_contacts = j.at("core_contacts").get<long>();
  r.core_missed = j.at("core_missed").get<long>();
  r.core_extra = j.at("core_extra").get<long>();
  r.candidates_differ = j.at("candidates_differ").get<long>();
  r.brute_missed = j.at("brute_missed").get<long>();
  r.discrete_passed = j.at("discrete_passed").get<long>();
  r.discrete_run_contacts = j.at("discrete_run_contacts").get<long>();
  r.impulse_contacts = j.at("impulse_contacts").get<long>();
  r.impulse_steps = j.at("impulse_steps").get<long>();
  return r;
}

}  // namespace tecido::suites::ccd
