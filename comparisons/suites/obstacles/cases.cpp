#include "comparisons/suites/obstacles/cases.h"

#include "comparisons/suites/obstacles/analytic_cases.h"
#include "comparisons/suites/obstacles/block_case.h"
#include "comparisons/suites/obstacles/bullet_cases.h"
#include "comparisons/suites/obstacles/fcl_cases.h"

#include <fmt/format.h>

namespace tecido::suites::obstacles {

std::string step_label(double h) { return fmt::format("{:g}", h); }

std::string block_name(int n, bool edge_contacts) {
  return fmt::format("block/{}/{}", n, edge_contacts ? "edges-on" : "edges-off");
}

std::string bullet_block_name(int n) { return fmt::format("bullet/block/{}", n); }

std::string fcl_block_name(int n) { return fmt::format("fcl/block/{}", n); }

std::vector<Case> cases(const Settings& s, const std::string& data_dir) {
  std::vector<Case> out;
  out.push_back({"sphere-drop", [s] { return sphere_drop_case(s); }});
  out.push_back({"slide", [s] { return slide_case(s); }});
  for (const char* kind : {"sphere", "box"})
    out.push_back({std::string("rest/") + kind, [s, k = std::string(kind)] { return rest_case(s, k); }});
  for (const std::string& scene : fast_scene_names())
    for (double h : s.fast_steps)
      out.push_back({"fast/" + scene + "/h=" + step_label(h), [s, scene, h] { return fast_case(s, scene, h); }});
  for (int n : s.block_sides)
    for (bool on : {false, true}) out.push_back({block_name(n, on), [s, data_dir, n, on] { return block_case(s, data_dir, n, on); }});
  out.push_back({"bullet/sphere", [s, data_dir] { return bullet_sphere_case(s, data_dir); }});
  for (int n : s.block_sides)
    out.push_back({bullet_block_name(n), [s, data_dir, n] { return bullet_block_case(s, data_dir, n); }});
  for (int n : s.block_sides)
    out.push_back({fcl_block_name(n), [s, data_dir, n] { return fcl_block_case(s, data_dir, n); }});
  return out;
}

}  // namespace tecido::suites::obstacles
