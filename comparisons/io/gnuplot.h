#pragma once
/// Plots through gnuplot, optional at run time: when gnuplot is missing the caller says so and
/// keeps its tables.
#include <string>

namespace tecido::io {

/// True when a `gnuplot` executable is on PATH.
bool gnuplot_available();

/// Runs gnuplot on `script` (text) with `dir` as working directory; data files named in the
/// script are relative to it. Returns true on success. The script is kept as dir/<name>.gp.
bool run_gnuplot(const std::string& dir, const std::string& name, const std::string& script);

}  // namespace tecido::io
