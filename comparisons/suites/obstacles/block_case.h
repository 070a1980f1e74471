#pragma once
/// One run of the block scene (block_scene.h) in core: the seed's artefact per frame.
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/obstacles/settings.h"

namespace tecido::suites::obstacles {

/// The n x n cloth on the block, edge contacts on or off, for block_seconds:
/// {"frames": [[t, springs through the block's interior, deepest such spring [m]], ...] at
/// block_frames equal intervals, "max_through" (most springs through at any step end),
/// "max_spring_depth" (deepest at any step end), "steps_inside" (particle step ends strictly inside
/// the block), "max_particle_depth", "t_onset" (first logged contact, "nan" if none),
/// "rest_height" (mean z - top at the end over the particles above the top face), "springs",
/// "unstable" (step or null)}.
io::Json block_case(const Settings& s, int n, bool edge_contacts);

}  // namespace tecido::suites::obstacles
