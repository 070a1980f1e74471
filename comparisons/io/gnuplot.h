#pragma once
/// Plots through gnuplot, optional at run time: when gnuplot is missing the caller says so and
/// keeps its tables.
#include <string>

namespace tecido::io {

/// True when a `gnuplot` executable is on PATH.
bool gnuplot_available();

/// Runs gnuplot on `script` (text) with `dir` as working directory; data files named in the
/// script are relative to it. The script is kept as dir/<name>.gp (written like every output:
/// OutputError when it cannot be). A script that draws into `<name>.svg` (`set output
/// '<name>.svg'`) draws into a temporary file instead, renamed to <name>.svg only when gnuplot
/// succeeded and the picture is complete (ends with </svg>), removed otherwise: a failed plot
/// (a full disk, a killed gnuplot) leaves no half-drawn picture. gnuplot runs without a shell,
/// so no path is ever interpreted. Returns true when the plot was drawn.
bool run_gnuplot(const std::string& dir, const std::string& name, const std::string& script);

}  // namespace tecido::io
