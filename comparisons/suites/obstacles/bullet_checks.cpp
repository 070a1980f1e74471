#include "comparisons/suites/obstacles/bullet_checks.h"

#include "comparisons/suites/sweep.h"

#include <cmath>

namespace tecido::suites::obstacles {

void declare_bullet_checks(CheckList& checks, const Settings& s, const Tolerances& tol) {
  std::vector<std::string> scenes = {"bullet/sphere"};
  for (int n : s.block_sides) scenes.push_back(bullet_block_name(n));
  for (const std::string& name : scenes) {
    const std::string b = "obstacles/" + name + "/";
    checks.declare(b + "onset_error", tol.at_most("/obstacles/bullet_onset_error_steps", s.block_dt),
                   "|Bullet's first contact - the analytic fall to its contact distance| [s]");
    checks.declare(b + "max_penetration", tol.at_most("/obstacles/bullet_max_penetration_m"),
                   "deepest Bullet node inside the obstacle over the run [m]");
    checks.declare(b + "rest_height_difference", tol.at_most("/obstacles/bullet_rest_height_m"),
                   "|Bullet's rest height on the obstacle - core's| [m]");
  }
}

void record_bullet(CheckList& checks, const Case& c, const io::Json& r) {
  const std::string b = "obstacles/" + c.name + "/";
  const io::Json& bt = r.at("bullet");
  const io::Json& core = r.at("core");
  checks.set(b + "onset_error", std::abs(get_num(bt.at("t_onset")) - get_num(r.at("t_onset_expected"))));
  checks.set(b + "max_penetration", get_num(bt.at("max_penetration")));
  checks.set(b + "rest_height_difference", std::abs(get_num(bt.at("rest_height")) - get_num(core.at("rest_height"))));
}

}  // namespace tecido::suites::obstacles
