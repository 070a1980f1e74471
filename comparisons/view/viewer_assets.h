#pragma once
/// The files every page needs beside it: tecido-viewer.js (web/src bundled with three.js by
/// esbuild into one classic script, which Chromium runs from file://; ES modules it refuses) and
/// tecido.css. Found, in order, in $TECIDO_VIEWER_DIR and in the build tree's web/ (the path is
/// compiled in, web/CMakeLists.txt).
#include <string>

namespace tecido::view {

/// The folder holding tecido-viewer.js and tecido.css; "" when none of the places has them.
std::string viewer_dir();

/// Copies tecido-viewer.js and tecido.css into `dir` (atomically, io/atomic_file.h) unless the
/// same files are there already. Returns false, copying nothing, when the viewer was not built;
/// the first time in a process it then prints a note on stderr saying so.
bool copy_viewer_assets(const std::string& dir);

}  // namespace tecido::view
