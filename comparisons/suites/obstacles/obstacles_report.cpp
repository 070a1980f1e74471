#include "comparisons/suites/obstacles/obstacles_report.h"

#include "comparisons/suites/sweep.h"

#include <fmt/format.h>

#include <algorithm>

namespace tecido::suites::obstacles {

const io::Json* completed_case(const Results& r, const std::string& name) {
  if (!r.contains(name)) return nullptr;
  const io::Json& j = r.at(name);
  return case_error(j) ? nullptr : &j;
}

namespace {

std::string err(const Results& r, const std::string& name) {
  if (!r.contains(name)) return "not run";
  const std::string* e = case_error(r.at(name));
  return e ? "failed: " + *e : "";
}

std::string g(const io::Json& j, const char* key) { return fmt::format("{:.6g}", get_num(j.at(key))); }

}  // namespace

std::string method_markdown(const Settings& s) {
  return fmt::format(
      "## obstacles\n\nParticles and a cloth against spheres and boxes, static and moving (core), the seed's "
      "cloth-on-a-block artefact as a table, and Bullet's classic soft body on the same scenes. Settings "
      "(`comparisons/suites/obstacles/settings.h`): g = {} m/s^2; drop {} m onto a sphere of radius {} m, k = {}, "
      "midpoint, dt = {} s; slide on a face tilted {:.4g} rad, mu = {}, dt = {} s for {} s; rest {} steps of {} s; "
      "fast cases {} steps each at dt in {{{}}} s, particle at {} m/s against a box {} m thick, bodies moving at {} m/s, "
      "a box spinning at {} rad/s; the block scenes data/scenes/{} and {} and the cloth on a sphere data/scenes/{} (their "
      "choices are documented in those files), run {}, {} frames counted; a spring is through the block when it goes "
      "deeper than {:g} m inside every face; Bullet's soft body with a collision margin of {} m and a distance-field "
      "voxel of {} m.\n\n",
      s.g, s.drop_height, s.sphere_radius, s.drop_elasticity, s.drop_dt, s.slide_angle, s.slide_friction, s.slide_dt,
      s.slide_seconds, s.rest_steps, s.rest_dt, s.fast_run_steps, fmt::join(s.fast_steps, ", "), s.fast_speed,
      2 * s.thin_half_thickness, s.moving_speed, s.spin_rate, s.block_files[0], s.block_files[1], s.sphere_file,
      s.block_seconds > 0.0 ? fmt::format("for {} s", s.block_seconds) : std::string("for each scene's own steps"),
      s.block_frames, s.through_depth, s.bullet_margin, s.bullet_voxel);
}

std::string analytic_markdown(const Settings& s, const Results& r) {
  std::string md = "### Analytic cases\n\n| case | quantity | core | closed form |\n|---|---|---|---|\n";
  if (const io::Json* d = completed_case(r, "sphere-drop")) {
    md += fmt::format("| sphere drop | contact time [s] | {} | {} |\n", g(*d, "t_core"), g(*d, "t_exact"));
    md += fmt::format("| sphere drop | rebound apex [m] (sampled: {}) | {} | {} |\n", g(*d, "apex_sampled"),
                      g(*d, "apex_core"), g(*d, "apex_expected"));
  }
  if (const io::Json* d = completed_case(r, "slide"))
    md += fmt::format("| slide | distance in {} s [m] (largest offset from the face {} m) | {} | {} |\n", s.slide_seconds,
                      g(*d, "max_offset"), g(*d, "distance"), g(*d, "expected"));
  for (const char* kind : {"rest/sphere", "rest/box"})
    if (const io::Json* d = completed_case(r, kind))
      md += fmt::format("| {} | largest offset [m], speed [m/s] over {} steps | {}, {} | 0, 0 |\n", kind, s.rest_steps,
                        g(*d, "max_offset"), g(*d, "max_speed"));
  for (const char* name : {"sphere-drop", "slide", "rest/sphere", "rest/box"})
    if (!err(r, name).empty()) md += fmt::format("| {} | {} | | |\n", name, err(r, name));
  if (const io::Json* d = completed_case(r, "slide"))
    md += fmt::format("\nThe seed's friction law scales the tangential velocity by (1 - mu) once per step, so the "
                      "slide tends to a h / mu = {} m/s, a speed that depends on the step (Coulomb friction would "
                      "give a constant deceleration); the closed form is that of the law.\n",
                      g(*d, "terminal_speed"));
  return md + "\n";
}

std::string fast_markdown(const Settings& s, const Results& r) {
  std::string md = "### Fast particles, huge steps, moving bodies\n\n| scene | dt [s] | step ends inside | tunnelled | "
                   "guard corrections | contacts |\n|---|---|---|---|---|---|\n";
  long long guards = 0;
  for (const std::string& scene : {std::string("thin-box"), std::string("moving-sphere"), std::string("moving-box"),
                                   std::string("spinning-box")})
    for (double h : s.fast_steps) {
      const std::string name = "fast/" + scene + "/h=" + step_label(h);
      const io::Json* d = completed_case(r, name);
      if (!d) {
        md += fmt::format("| {} | {} | {} | | | |\n", scene, step_label(h), err(r, name));
        continue;
      }
      guards += d->at("guard_corrections").get<long long>();
      md += fmt::format("| {} | {} | {} | {} | {} | {} |\n", scene, step_label(h), d->at("steps_inside").dump(),
                        d->at("tunnelled").dump(), d->at("guard_corrections").dump(), d->at("contacts").dump());
    }
  md += fmt::format("\nCore's end-of-step guard pushed a particle out {} times in these runs (each one a contact the "
                    "continuous test did not place; the step still ends outside).\n\n",
                    guards);
  return md;
}

}  // namespace tecido::suites::obstacles
