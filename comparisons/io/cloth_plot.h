#pragma once
/// A picture of a few key frames of a run (the cloth as a wire mesh, or the particles as
/// points when the scene has no triangles), side by side, through gnuplot (svg terminal).
/// The vertical axis of the picture is the scene axis most opposed to gravity (z without
/// gravity); all panels share one set of axis ranges and equal scales, so they compare.
/// Writes DIR/NAME.dat (the mesh edges, one gnuplot index per frame), DIR/NAME.gp and, when
/// gnuplot is on PATH, DIR/NAME.svg; otherwise says so and skips the image.
#include "core/geometry/types.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace tecido::io {

struct PlotFrame {
  long long step = 0;
  double time = 0.0;
  std::vector<Vec3> x;
};

/// Returns true when the SVG was written; otherwise `why` says why (gnuplot missing or failed,
/// nothing to plot). `gravity` picks the vertical axis.
bool plot_cloth_frames(const std::string& dir, const std::string& name, const std::string& title,
                       const std::vector<PlotFrame>& frames, const std::vector<std::array<int, 3>>& triangles,
                       const std::optional<Vec3>& gravity, std::string* why);

}  // namespace tecido::io
