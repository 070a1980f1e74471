#include "comparisons/suites/obstacles/bullet_checks.h"

#include "comparisons/suites/sweep.h"

#include <cmath>

namespace tecido::suites::obstacles {

void declare_bullet_checks(CheckList& checks, const Settings& s, const Tolerances& tol) {
  std::vector<std::string> scenes = {"bullet/sphere"};
  for (int n : s.block_sides) scenes.push_back(bullet_block_name(n));
  for (const std::string& name : scenes) {
    const std::string b = "obstacles/" + name + "/";
    checks.declare(b + "onset_error_steps", tol.at_most("/obstacles/bullet_onset_error_steps"),
                   "|Bullet's contact onset - the analytic fall to the surface| in steps of the scene's dt");
  }
}

void record_bullet(CheckList& checks, const Case& c, const io::Json& r) {
  const std::string b = "obstacles/" + c.name + "/";
  const io::Json& bt = r.at("bullet");
  checks.set(b + "onset_error_steps",
             std::abs(get_num(bt.at("t_onset")) - get_num(r.at("t_onset_expected"))) / get_num(r.at("dt")));
}

}  // namespace tecido::suites::obstacles
