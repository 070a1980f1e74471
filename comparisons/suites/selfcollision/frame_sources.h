#pragma once
/// Where the `selfcollision` suite's frames come from: one function per source, listed in a
/// table. A source is one case of the suite's sweep, and its checks are declared from the table,
/// so adding a source is adding one entry.
#include "comparisons/suites/selfcollision/frame_recorder.h"
#include "comparisons/suites/selfcollision/settings.h"

#include <string>
#include <vector>

namespace tecido::suites::selfcollision {

struct FrameSource {
  std::string name;   ///< "seed-fig21", "crumple": the middle part of the source's check names
  std::string about;  ///< one line for the report
  /// Records the source's frames; `data_dir` is data/ (scenes).
  FrameSet (*record)(const Settings& s, const std::string& data_dir);
};

/// The seed's experiment scene (fig. 21, data/scenes/seed_fig21_self_contact.json) without a
/// self-collision response, so its contacts stay: a frame every s.seed_frame_interval seconds.
FrameSet seed_fig21_frames(const Settings& s, const std::string& data_dir);

/// A soft s.crumple_grid^2 cloth dropped at an angle onto a floor, crumpling into itself.
FrameSet crumple_frames(const Settings& s, const std::string& data_dir);

/// Every source, in report order.
const std::vector<FrameSource>& frame_sources();

}  // namespace tecido::suites::selfcollision
