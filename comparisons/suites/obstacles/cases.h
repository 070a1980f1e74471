#pragma once
/// The `obstacles` suite's cases, listed in a table by index: case k is a pure function of the
/// settings and k. Each case's checks share the prefix "obstacles/<case name>/", so a case that
/// throws fails exactly its own checks.
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/obstacles/settings.h"

#include <functional>
#include <string>
#include <vector>

namespace tecido::suites::obstacles {

struct Case {
  std::string name;  ///< "sphere-drop", "rest/box", "fast/thin-box/h=10", "block/11/edges-off", ...
  std::function<io::Json()> run;
};

/// The step of a fast case as it appears in names ("0.001", "10").
std::string step_label(double h);
/// "block/<n>/edges-on" or ".../edges-off".
std::string block_name(int n, bool edge_contacts);
/// "bullet/block/<n>" and "bullet/sphere": the Bullet runs of the scenes (reference build only).
std::string bullet_block_name(int n);
/// "fcl/block/<n>": FCL's contact time on the block scene (reference build only, reported).
std::string fcl_block_name(int n);

/// Every case, in a fixed order (the block and sphere scenes read from data_dir/scenes): analytic (sphere drop, slide, rest on sphere and box), fast
/// (scene-major, then step), block (side-major, edges off then on), then, in the reference build,
/// the Bullet runs (sphere, then each block side) and FCL's contact times (each block side).
std::vector<Case> cases(const Settings& s, const std::string& data_dir);

}  // namespace tecido::suites::obstacles
