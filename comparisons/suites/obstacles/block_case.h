#pragma once
/// One run of the block scene (block_scene.h) in core: the seed's artefact per frame.
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/obstacles/settings.h"

#include <string>

namespace tecido::suites::obstacles {

/// The n x n cloth on the block (block_scene.h), edge contacts on or off, for run_steps steps:
/// {"frames": [[t, springs through the block's interior, deepest such spring [m]], ...] at
/// block_frames equal intervals, "max_through" (most springs through at any step end),
/// "max_spring_depth" (deepest at any step end), "steps_inside" (particle step ends strictly inside
/// the block), "max_particle_depth", "t_onset" (first logged contact, "nan" if none),
/// "rest_height" (mean height above the top at the end of the particles over the top face, within
/// 1 mm below it or higher), "springs", and at the run's end "end_time", "end_through" (springs
/// through the block's interior), "end_depth" (the deepest of them [m], 0 when none), with the
/// scene's "spacing" [m], "insets" (edge_insets: the block's four top edges against the grid, in
/// spacings) and "across" (springs_across_outline),
/// "unstable" (step or null), and "view": the run's page data (view/run_view.h: the start and the
/// counted frames, the springs through the block in each) that the suite writes as a page and
/// keeps out of report.json}.
io::Json block_case(const Settings& s, const std::string& data_dir, int n, bool edge_contacts);

}  // namespace tecido::suites::obstacles
