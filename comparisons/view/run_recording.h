#pragma once
/// A run recorded for its page without `tecido run`: the scene simulated by core (its
/// self-collision response installed when it has one, as `tecido run` does) and a frame kept every
/// `every` steps, and the last, into a RunView (run_view.h; thinned by view_frame_stride). Used by
/// `tecido experiment self-contact --view`, whose runs are built from a cell, not read from a file.
#include "comparisons/io/json_reader.h"
#include "core/scene/scene.h"

#include <string>

namespace tecido::view {

/// The page data of `scene` run for scene.steps steps (fewer when it goes unstable; frames with a
/// non-finite position are not kept).
io::Json record_run_page(const Scene& scene, long long every, const std::string& title);

}  // namespace tecido::view
