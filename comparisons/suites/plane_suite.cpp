#include "comparisons/suites/plane_suite.h"

#include "comparisons/engines/segment_plane_engines.h"
#include "comparisons/io/atomic_file.h"
#include "comparisons/io/gnuplot.h"
#include "comparisons/suites/random.h"
#include "core/dynamics/simulation.h"

#include <fmt/format.h>

#ifdef TECIDO_HAVE_REFERENCE
#include "reference/bullet_deformable.h"
#include "reference/bullet_rigid_drop.h"
#endif

#include <chrono>
#include <cmath>
#include <map>

namespace tecido::suites {

std::string case_category(const std::string& id) { return id.substr(0, id.find('/')); }

namespace {

BoundedPlane random_plane(Rng& r, const Vec3& centre) {
  const Vec3 n = r.unit_vector();
  Vec3 f = r.unit_vector();
  while (n.cross(f).norm() < 0.1) f = r.unit_vector();
  return make_bounded_plane(centre, n, f, Vec2(r.uniform(0.1, 2.0), r.uniform(0.1, 2.0)), 0.0);
}

/// Axis-aligned plane at a dyadic height, so that "on the plane" is exactly representable.
BoundedPlane flat_plane(Rng& r) {
  const double z = std::ldexp(static_cast<double>(r.below(64)) - 32.0, -3);
  const Vec3 f = r.below(2) ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  return make_bounded_plane(Vec3(std::ldexp(static_cast<double>(r.below(16)), -2), 0.5, z), Vec3(0, 0, 1), f,
                            Vec2(std::ldexp(1.0 + static_cast<double>(r.below(8)), -2), std::ldexp(1.0 + static_cast<double>(r.below(8)), -2)), 0.0);
}

/// A segment through point c along a direction not parallel to the plane.
std::pair<Vec3, Vec3> through(Rng& r, const BoundedPlane& p, const Vec3& c) {
  Vec3 d = r.unit_vector();
  if (std::abs(d.dot(p.normal)) < 0.2) d += p.normal;
  const double a = r.uniform(0.05, 1.5), b = r.uniform(0.05, 1.5);
  return {c - a * d, c + b * d};
}

}  // namespace

std::vector<io::PlaneCase> make_plane_cases(std::uint64_t seed, int n_random, int n_per_category) {
  std::vector<io::PlaneCase> out;
  auto add = [&](const std::string& cat, int k, const BoundedPlane& p, const Vec3& a, const Vec3& b) {
    out.push_back(io::PlaneCase{cat + "/" + std::to_string(k), p, a, b});
  };
  const char* categories[] = {"random", "edge", "corner", "grazing", "parallel", "in-plane", "start-on", "end-on", "far"};
  for (std::uint64_t ci = 0; ci < 9; ++ci) {
    const std::string cat = categories[ci];
    const int n = ci == 0 ? n_random : n_per_category;
    for (int k = 0; k < n; ++k) {
      Rng r(substream(seed, ci * 100000000ULL + static_cast<std::uint64_t>(k)));
      if (cat == "random" || cat == "far") {
        const double off = cat == "far" ? std::pow(10.0, 3 + static_cast<double>(k % 6)) : 0.0;
        const Vec3 shift = off * r.unit_vector();
        const BoundedPlane p = random_plane(r, shift + r.in_box(-0.5, 0.5));
        add(cat, k, p, shift + r.in_box(-2.5, 2.5), shift + r.in_box(-2.5, 2.5));
      } else if (cat == "edge") {
        const BoundedPlane p = random_plane(r, r.in_box(-1, 1));
        const double sa = r.below(2) ? 1.0 : -1.0;
        const Vec3 c = r.below(2) ? p.position + sa * p.half_extents.x() * p.forward + r.uniform(-1, 1) * p.half_extents.y() * p.right()
                                  : p.position + r.uniform(-1, 1) * p.half_extents.x() * p.forward + sa * p.half_extents.y() * p.right();
        const auto [a, b] = through(r, p, c);
        add(cat, k, p, a, b);
      } else if (cat == "corner") {
        const BoundedPlane p = random_plane(r, r.in_box(-1, 1));
        const Vec3 c = p.position + (r.below(2) ? 1.0 : -1.0) * p.half_extents.x() * p.forward +
                       (r.below(2) ? 1.0 : -1.0) * p.half_extents.y() * p.right();
        const auto [a, b] = through(r, p, c);
        add(cat, k, p, a, b);
      } else if (cat == "grazing") {
        const BoundedPlane p = random_plane(r, r.in_box(-1, 1));
        const Vec3 c = p.position + r.uniform(-1.2, 1.2) * p.half_extents.x() * p.forward +
                       r.uniform(-1.2, 1.2) * p.half_extents.y() * p.right();
        const Vec3 t = (r.uniform(-1, 1) * p.forward + r.uniform(-1, 1) * p.right()).normalized();
        const Vec3 d = (t + std::pow(10.0, r.uniform(-12, -3)) * (r.below(2) ? 1.0 : -1.0) * p.normal).normalized();
        const double a = r.uniform(0.1, 1.0), b = r.uniform(0.1, 1.0);
        add(cat, k, p, c - a * d, c + b * d);
      } else if (cat == "parallel") {
        const BoundedPlane p = flat_plane(r);
        const double dz = std::ldexp(1.0, -static_cast<int>(r.below(40)));  // 1 down to 2^-39 above or below
        const double z = p.position.z() + (r.below(2) ? dz : -dz);
        add(cat, k, p, Vec3(r.uniform(-3, 3), r.uniform(-3, 3), z), Vec3(r.uniform(-3, 3), r.uniform(-3, 3), z));
      } else if (cat == "in-plane") {
        const BoundedPlane p = flat_plane(r);
        const double z = p.position.z();
        add(cat, k, p, Vec3(r.uniform(-2, 3), r.uniform(-1.5, 2.5), z), Vec3(r.uniform(-2, 3), r.uniform(-1.5, 2.5), z));
      } else {  // start-on / end-on
        const BoundedPlane p = flat_plane(r);
        const Vec3 on(r.uniform(-2, 3), r.uniform(-1.5, 2.5), p.position.z());
        const Vec3 off = on + Vec3(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(0.01, 1) * (r.below(2) ? 1.0 : -1.0));
        if (cat == "start-on") add(cat, k, p, on, off);
        else add(cat, k, p, off, on);
      }
    }
  }
  return out;
}

namespace {

struct Tally {
  long n = 0, agree = 0, false_hit = 0, missed = 0, null = 0;
  double t_err_max = 0.0;
};

double analytic_drop_time(double z0, double vz0, double g) {  // root of z0 + vz0 t - g t^2/2
  return (vz0 + std::sqrt(vz0 * vz0 + 2.0 * g * z0)) / g;
}

}  // namespace

SuiteResult run_plane_suite(const SuiteContext& ctx) {
  SuiteResult res;
  res.name = "plane";
  const Tolerances& tol = *ctx.tolerances;
  const std::string dir = ctx.out_dir + "/plane";
  const int n_random = ctx.quick ? 2000 : 10000;
  const int n_cat = ctx.quick ? 250 : 2000;
  const auto cases = make_plane_cases(substream(ctx.seed, 1), n_random, n_cat);

  const SegmentPlaneEngine* referee = find_segment_plane_engine("exact");
  std::string md;
  io::Json data = io::Json::object();
  if (!referee) {
    md += "The exact referee is not built in (reference adapters off), so static agreement is not measured.\n\n";
  } else {
  std::vector<std::optional<SegmentPlaneHit>> truth(cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) truth[i] = referee->test(cases[i].plane, cases[i].from, cases[i].to);

  const std::vector<std::string> cats = {"random", "edge", "corner", "grazing", "parallel", "in-plane", "start-on", "end-on", "far"};
  md += fmt::format(
      "{} cases ({} random, {} per adversarial category), seed {}: every engine's hit against the exact referee (CGAL/GMP "
      "rationals on the same doubles), and the largest crossing-fraction error |t - t_exact| where both hit. `core` decides "
      "exactly; `core-seed`, the seed's floating-point test as written, is reported, not checked.\n\n",
      cases.size(), n_random, n_cat, ctx.seed);
  md += "| engine | category | cases | agree | false hits | misses | no answer | max t error | ns/case |\n|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
  std::vector<io::PlaneCase> disagreements;
  for (const auto& eng : segment_plane_engines()) {
    if (eng.name == "exact") continue;
    std::map<std::string, Tally> by_cat;
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<std::optional<SegmentPlaneHit>> got(cases.size());
    for (std::size_t i = 0; i < cases.size(); ++i) got[i] = eng.test(cases[i].plane, cases[i].from, cases[i].to);
    const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() / cases.size();
    for (std::size_t i = 0; i < cases.size(); ++i) {
      Tally& t = by_cat[case_category(cases[i].id)];
      ++t.n;
      if (!got[i] || !truth[i]) {
        ++t.null;
        continue;
      }
      if (got[i]->hit == truth[i]->hit) {
        ++t.agree;
        if (got[i]->hit) t.t_err_max = std::max(t.t_err_max, std::abs(got[i]->t - truth[i]->t));
      } else {
        (got[i]->hit ? t.false_hit : t.missed)++;
        io::PlaneCase c = cases[i];
        c.id = eng.name + ":" + c.id;
        disagreements.push_back(c);
      }
    }
    for (const auto& cat : cats) {
      const Tally& t = by_cat[cat];
      md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {:.2e} | {} |\n", eng.name, cat, t.n, t.agree, t.false_hit,
                        t.missed, t.null, t.t_err_max, cat == "random" ? fmt::format("{:.0f}", ns) : "");
      data[eng.name][cat] = {{"cases", t.n}, {"agree", t.agree}, {"false_hits", t.false_hit}, {"misses", t.missed},
                             {"null", t.null}, {"max_t_error", t.t_err_max}};
    }
    data[eng.name]["ns_per_case"] = ns;
    // The seed's floating-point test as written (core-seed) is reported, not checked, like the
    // seed's triangle tests in the tritri suite.
    if (eng.name.rfind("core-", 0) == 0) continue;
    // Groups: random; border (edge, corner: the crossing lies on the border up to one rounding,
    // so a floating-point test decides by rounding); exact-geometry (parallel, in-plane,
    // start-on, end-on: built exactly on an axis-aligned plane); grazing (ill-conditioned
    // crossing fraction, agreement only); far (offsets 1e3..1e8).
    const std::vector<std::pair<std::string, std::vector<std::string>>> groups = {
        {"random", {"random"}}, {"border", {"edge", "corner"}}, {"exact-geometry", {"parallel", "in-plane", "start-on", "end-on"}},
        {"grazing", {"grazing"}}, {"far", {"far"}}};
    for (const auto& [group, members] : groups) {
      Tally g;
      for (const auto& m : members) {
        const Tally& t = by_cat[m];
        g.n += t.n;
        g.agree += t.agree;
        g.t_err_max = std::max(g.t_err_max, t.t_err_max);
      }
      const std::string base = "plane/" + eng.name + "/";
      res.checks.push_back(make_check(base + "agreement/" + group, g.n ? double(g.agree) / g.n : std::nan(""),
                                      tol.get("/plane/" + eng.name + "_agreement_" + group), 1.0));
      if (group != "grazing")
        res.checks.push_back(make_check(base + "t_error/" + group, g.t_err_max, 0.0,
                                        tol.get("/plane/" + eng.name + "_t_error_" + (group == "far" ? "far" : "near"))));
    }
  }
  io::write_file_atomic(dir + "/disagreements.json", io::plane_cases_to_json(disagreements).dump(1) + "\n");
  md += fmt::format("\n{} disagreements are in `plane/disagreements.json` (ids prefixed by the engine); "
                    "`tecido plane --cases out/plane/disagreements.json --json` re-runs them.\n\n",
                    disagreements.size());
  }

  // Dynamic: ballistic drops, bisected time of contact vs the analytic root.
  md += "### Time of contact by bisection (fig. 8)\n\nA particle dropped from random heights and speeds onto a floor, "
        "under gravity; the time of the first contact from the contact log against the root of z0 + vz0 t - g t^2/2. "
        "Midpoint integrates constant acceleration exactly, so its error is the bisection's alone; symplectic Euler's "
        "sub-step is not exact, so its error also holds the integrator's O(h) position error. "
        "Tolerance = h · 2^-k; cost in integrator calls (bisections) per contact.\n\n";
  md += "| integrator | h [s] | k | tolerance [s] | max \\|t - t_exact\\| [s] | bisections per contact | µs per drop (whole run to first contact) |\n|---|---:|---:|---:|---:|---:|---:|\n";
  const int drops = ctx.quick ? 20 : 100;
  std::string dat;
  for (IntegratorKind integ : {IntegratorKind::Midpoint, IntegratorKind::Symplectic}) {
    for (double h : {0.1, 0.02, 0.005}) {
      double worst_ratio = 0.0;
      for (int k : {4, 8, 12, 16, 20, 24, 28}) {
        const double tolerance = std::ldexp(h, -k);
        double err_max = 0.0, bis = 0.0, secs = 0.0;
        for (int d = 0; d < drops; ++d) {
          Rng r(substream(ctx.seed, 777000 + d));
          const double z0 = r.uniform(0.2, 5.0), vz0 = r.uniform(-3.0, 3.0);
          Scene s;
          s.integrator = integ;
          s.dt = h;
          s.contact.bisection_tolerance = tolerance;
          s.forces.gravity = Vec3(0, 0, -9.81);
          s.particles.add(Vec3(0, 0, z0), Vec3(r.uniform(-1, 1), r.uniform(-1, 1), vz0), 1.0, 0.5, false);
          s.planes.push_back(make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), Vec2(100, 100), 0.0));
          Simulation sim(s);
          sim.set_log_contacts(true);
          const auto t0 = std::chrono::steady_clock::now();
          while (sim.contact_log().empty() && sim.time() < 10.0) sim.step();
          secs += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          if (sim.contact_log().empty()) {
            err_max = std::numeric_limits<double>::infinity();
            continue;
          }
          err_max = std::max(err_max, std::abs(sim.contact_log().front().time - analytic_drop_time(z0, vz0, 9.81)));
          bis += static_cast<double>(sim.contacts().bisections);
        }
        md += fmt::format("| {} | {} | {} | {:.3g} | {:.3g} | {:.1f} | {:.2f} |\n", integrator_name(integ), h, k, tolerance,
                          err_max, bis / drops, 1e6 * secs / drops);
        dat += fmt::format("{} {} {:.17g} {:.17g} {:.17g}\n", integrator_name(integ), h, tolerance, err_max, bis / drops);
        if (integ == IntegratorKind::Midpoint) worst_ratio = std::max(worst_ratio, err_max / tolerance);
      }
      if (integ == IntegratorKind::Midpoint) {
        res.checks.push_back(make_check(fmt::format("plane/contact_time/midpoint/h={}", h), worst_ratio, 0.0,
                                        tol.get("/plane/contact_time_over_tolerance")));
      }
    }
  }
  io::write_file_atomic(dir + "/contact_time.dat", dat);
#ifdef TECIDO_HAVE_REFERENCE
  {
    // The same drops in Bullet: a small rigid sphere on a static plane, and a soft-body node
    // (the deformable twin) on a bounded plane. Contact time and rebound height (apex above the
    // plane after the first bounce) against the analytic values and core's (midpoint, k = 0.5).
    const double h = 0.005, g = 9.81, k = 0.5;
    md += fmt::format("\n### The same drops in Bullet\n\nA particle dropped from rest at height z0 onto a floor, "
                      "restitution k = {}, dt = {} s. Analytic contact time sqrt(2 z0 / g) and rebound apex k^2 z0. "
                      "Core: bisected contact, midpoint. Bullet rigid: a sphere of radius 1 mm (btSphereShape on "
                      "btStaticPlaneShape; restitution sqrt(k) on each body, which Bullet multiplies), contact = the "
                      "step whose impulse lifts it, heights of its lowest point. Bullet soft node: the deformable "
                      "twin (one node), contact = first step within its collision margin.\n\n",
                      k, h);
    md += "| z0 [m] | t analytic [s] | t core | t Bullet rigid | t Bullet node | apex analytic [m] | apex core | apex Bullet rigid | apex Bullet node |\n"
          "|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    double worst_core = 0.0, worst_rigid = 0.0;
    for (double z0 : {0.2, 1.0, 3.0}) {
      const double t_exact = std::sqrt(2.0 * z0 / g), apex_exact = k * k * z0;
      Scene s;
      s.integrator = IntegratorKind::Midpoint;
      s.dt = h;
      s.forces.gravity = Vec3(0, 0, -g);
      s.particles.add(Vec3(0, 0, z0), Vec3::Zero(), 1.0, k, false);
      s.planes.push_back(make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), Vec2(10, 10), 0.0));
      Simulation sim(s);
      sim.set_log_contacts(true);
      double apex_core = -1.0;
      const double T = t_exact + 2.0 * k * std::sqrt(2.0 * g * z0) / g * 0.75;  // into the first rebound's fall
      while (sim.time() < T && sim.step())
        if (!sim.contact_log().empty()) apex_core = std::max(apex_core, sim.particles().x[0].z());
      const double t_core = sim.contact_log().empty() ? std::nan("") : sim.contact_log().front().time;
      const auto rigid = reference::bullet_sphere_drop(z0, 0.0, g, k, 1e-3, h, T);
      reference::DeformableTwin twin(s);
      double t_node = std::nan(""), apex_node = -1.0;
      while (twin.time() < T && twin.step()) {
        const double z = twin.positions()[0].z();
        if (std::isnan(t_node) && z <= twin.plane_contact_offset() + 1e-6) t_node = twin.time();
        if (!std::isnan(t_node)) apex_node = std::max(apex_node, z);
      }
      md += fmt::format("| {} | {:.5f} | {:.5f} | {:.5f} | {:.5f} | {:.4f} | {:.4f} | {:.4f} | {:.4f} |\n", z0, t_exact, t_core,
                        rigid.contact_time, t_node, apex_exact, apex_core, rigid.rebound_apex, apex_node);
      worst_core = std::max(worst_core, std::abs(apex_core - apex_exact) / apex_exact);
      worst_rigid = std::max(worst_rigid, std::abs(rigid.contact_time - t_exact));
    }
    md += "\nThe deformable world's node contact is inelastic: it keeps the node at its margin and has no "
          "restitution, so its apex stays at the margin (restitution is listed as not modelled by the twin).\n";
    res.checks.push_back(make_check("plane/drop/core_apex_rel_error", worst_core, 0.0, tol.get("/plane/drop_core_apex_rel")));
    res.checks.push_back(make_check("plane/drop/bullet_rigid_contact_time_error", worst_rigid, 0.0, 2.0 * h));
  }
#endif
  md += "\nEach extra bisection level halves the bracket for one more integrator call per contact; with midpoint the "
        "error follows the tolerance down to round-off, with symplectic Euler it stops at the integrator's own error.\n";
  res.markdown = md;
  res.data = data;
  return res;
}

}  // namespace tecido::suites
