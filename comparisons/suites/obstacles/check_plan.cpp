#include "comparisons/suites/obstacles/check_plan.h"

#include "comparisons/suites/obstacles/analytic_cases.h"
#include "comparisons/suites/obstacles/bullet_checks.h"
#include "comparisons/suites/sweep.h"

#include <algorithm>
#include <cmath>

namespace tecido::suites::obstacles {

namespace {

const char* const kT = "/obstacles/";

std::string p(const char* key) { return std::string(kT) + key; }

void declare_analytic(CheckList& c, const Settings& s, const Tolerances& tol) {
  c.declare("obstacles/sphere-drop/contact_time_error", tol.at_most(p("contact_time_error_steps"), s.drop_dt),
            "|t_core - sqrt(2h/g)| [s] of a particle dropped on a sphere (band in steps x dt)");
  c.declare("obstacles/sphere-drop/apex_rel_error", tol.at_most(p("apex_rel_error")),
            "|apex / (k^2 h) - 1| after the first bounce on the sphere");
  c.declare("obstacles/slide/distance_rel_error", tol.at_most(p("slide_rel_error")),
            "|distance / closed form - 1| sliding down a tilted box face with the seed's friction law");
  c.declare("obstacles/slide/max_offset", tol.at_most(p("surface_offset_m")),
            "largest |distance from the face| [m] while sliding");
  for (const char* kind : {"sphere", "box"}) {
    const std::string b = std::string("obstacles/rest/") + kind;
    c.declare(b + "/max_offset", tol.at_most(p("surface_offset_m")),
              "largest |distance from the surface| [m] over the resting run (sinking or jitter)");
    c.declare(b + "/max_speed", tol.at_most(p("rest_speed")), "largest speed [m/s] over the resting run");
  }
  for (const std::string& scene : fast_scene_names())
    for (double h : s.fast_steps) {
      const std::string b = "obstacles/fast/" + scene + "/h=" + step_label(h);
      c.declare(b + "/steps_inside", tol.at_most(p("steps_inside")), "step ends with the particle inside an obstacle");
      if (scene == "thin-box")
        c.declare(b + "/tunnelled", tol.at_most(p("tunnelled")), "step ends past the thin box's far face");
    }
}

void declare_block(CheckList& c, const Settings& s, const Tolerances& tol) {
  for (int n : s.block_sides)
    for (bool on : {false, true}) {
      const std::string b = "obstacles/" + block_name(n, on);
      c.declare(b + "/steps_inside", tol.at_most(p("steps_inside")),
                "particle step ends strictly inside the block");
      if (on)
        c.declare(b + "/max_springs_through", tol.at_most(p("springs_through_edge_contacts")),
                  "most springs through the block's interior at any step end, edge contacts on");
    }
  const std::string m = "obstacles/block/matched/";
  c.declare(m + "inset_difference", tol.at_most(p("matched_inset_difference")),
            "largest |inset at 121 - inset at 484| over the block's four top edges [spacings]: both scenes place the "
            "block alike against their grids");
  c.declare(m + "depth_per_spacing_ratio", tol.around(p("matched_depth_margin"), 1.0),
            "edges off, at the run's end: deepest spring inside the block over the spacing, 484 particles over 121");
  c.declare(m + "cut_share_ratio", tol.around(p("matched_cut_margin"), 1.0),
            "edges off, at the run's end: springs through the block over springs across the top face's outline at "
            "t = 0, 484 particles over 121");
}

void fail_all(CheckList& checks, const Case& c, const std::string& reason) {
  checks.fail_pending("obstacles/" + c.name + "/", reason);
}

double rel_error(double value, double expected) { return std::abs(value / expected - 1.0); }

void record_analytic(CheckList& checks, const Case& c, const io::Json& r) {
  const std::string b = "obstacles/" + c.name + "/";
  if (c.name == "sphere-drop") {
    checks.set(b + "contact_time_error", std::abs(get_num(r.at("t_core")) - get_num(r.at("t_exact"))));
    checks.set(b + "apex_rel_error", rel_error(get_num(r.at("apex_core")), get_num(r.at("apex_expected"))));
  } else if (c.name == "slide") {
    checks.set(b + "distance_rel_error", rel_error(get_num(r.at("distance")), get_num(r.at("expected"))));
    checks.set(b + "max_offset", get_num(r.at("max_offset")));
  } else if (c.name.rfind("rest/", 0) == 0) {
    checks.set(b + "max_offset", get_num(r.at("max_offset")));
    checks.set(b + "max_speed", get_num(r.at("max_speed")));
  } else if (c.name.rfind("fast/", 0) == 0) {
    checks.set(b + "steps_inside", r.at("steps_inside").get<double>());
    if (checks.declared(b + "tunnelled")) checks.set(b + "tunnelled", r.at("tunnelled").get<double>());
  }
}

void record_block(CheckList& checks, const Case& c, const io::Json& r) {
  const std::string b = "obstacles/" + c.name + "/";
  checks.set(b + "steps_inside", r.at("steps_inside").get<double>());
  if (checks.declared(b + "max_springs_through")) checks.set(b + "max_springs_through", r.at("max_through").get<double>());
}

}  // namespace

CheckList declare_checks(const Settings& s, const Tolerances& tol, bool reference) {
  CheckList c;
  declare_analytic(c, s, tol);
  declare_block(c, s, tol);
  if (reference) declare_bullet_checks(c, s, tol);
  return c;
}

void record_matched(CheckList& checks, const Settings& s, const io::Json& by_name) {
  const std::string b = "obstacles/block/matched/";
  const io::Json& coarse = by_name.at(block_name(s.block_sides[0], false));
  const io::Json& fine = by_name.at(block_name(s.block_sides[1], false));
  for (const io::Json* r : {&coarse, &fine}) {
    if (const std::string* err = case_error(*r)) return checks.fail_pending(b, "a block run threw: " + *err);
    if (!r->at("unstable").is_null()) return checks.fail_pending(b, "a block run went unstable");
  }
  double inset_difference = 0.0;
  for (std::size_t e = 0; e < 4; ++e)
    inset_difference =
        std::max(inset_difference, std::abs(get_num(coarse.at("insets")[e]) - get_num(fine.at("insets")[e])));
  checks.set(b + "inset_difference", inset_difference);
  auto depth = [](const io::Json& r) { return get_num(r.at("end_depth")) / get_num(r.at("spacing")); };
  auto share = [](const io::Json& r) { return r.at("end_through").get<double>() / r.at("across").get<double>(); };
  checks.set(b + "depth_per_spacing_ratio", depth(fine) / depth(coarse));
  checks.set(b + "cut_share_ratio", share(fine) / share(coarse));
}

void record(CheckList& checks, const Settings& s, const Case& c, const io::Json& result) {
  (void)s;
  if (const std::string* err = case_error(result)) return fail_all(checks, c, "case threw: " + *err);
  if (result.contains("unstable") && !result.at("unstable").is_null())
    return fail_all(checks, c, "unstable at step " + result.at("unstable").dump());
  if (c.name.rfind("block/", 0) == 0) return record_block(checks, c, result);
  if (c.name.rfind("bullet/", 0) == 0) return record_bullet(checks, c, result);
  record_analytic(checks, c, result);
}

}  // namespace tecido::suites::obstacles
