#pragma once
/// Frames a person can open: one file per written frame, particle positions in particle order
/// and the scene's triangles (the cloth), in Wavefront OBJ and/or legacy VTK.
///  - OBJ: "v x y z" per particle, then "f a b c" per triangle (1-based); with no triangles the
///    file is a point cloud (vertices only).
///  - VTK: ASCII legacy "POLYDATA" with POINTS, POLYGONS (or VERTICES when there is no triangle)
///    and the particle velocities as POINT_DATA VECTORS "velocity" (ParaView, VisIt).
/// Files are DIR/frame_<step, 6 digits>.obj|.vtk, each written atomically (a file that cannot be
/// written is an io::OutputError naming it). Positions are printed
/// with 9 significant digits (enough to view, not to restart a run: result.json has 17).
#include "core/geometry/types.h"

#include <array>
#include <string>
#include <vector>

namespace tecido::io {

/// The OBJ text of one frame; `comment` becomes the first line after "# ".
std::string obj_frame_text(const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles,
                           const std::string& comment);

/// The legacy VTK text of one frame (v may be empty: no velocity field).
std::string vtk_frame_text(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                           const std::vector<std::array<int, 3>>& triangles, const std::string& title);

class FrameWriter {
 public:
  /// Writes into `dir` (created on first write), OBJ and/or VTK.
  FrameWriter(std::string dir, bool obj, bool vtk) : dir_(std::move(dir)), obj_(obj), vtk_(vtk) {}

  /// Writes the frame of `step` at time t. Frames with a non-finite position are skipped
  /// (returns false): viewers cannot read NaN.
  bool write(long long step, double t, const std::vector<Vec3>& x, const std::vector<Vec3>& v,
             const std::vector<std::array<int, 3>>& triangles);

  long long written() const { return written_; }
  const std::string& dir() const { return dir_; }

 private:
  std::string dir_;
  bool obj_, vtk_;
  long long written_ = 0;
};

}  // namespace tecido::io
