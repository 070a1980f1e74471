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
/// A scene's obstacles (obstacle_surfaces.h), when given, follow the particles: in OBJ each as its
/// own object ("o obstacle_k", its vertices after the particles'); in VTK as more points and
/// polygons (velocity 0) with a cell field "body" (0 = the scene's own cells, k + 1 = obstacle k).
#include "comparisons/io/obstacle_surfaces.h"
#include "core/geometry/types.h"

#include <array>
#include <string>
#include <vector>

namespace tecido::io {

/// The OBJ text of one frame; `comment` becomes the first line after "# ". Coordinates have `digits`
/// significant digits (17: the doubles round-trip).
std::string obj_frame_text(const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles,
                           const std::string& comment, const std::vector<SurfaceMesh>& obstacles = {}, int digits = 9);

/// The legacy VTK text of one frame (v may be empty: no velocity field).
std::string vtk_frame_text(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                           const std::vector<std::array<int, 3>>& triangles, const std::string& title,
                           const std::vector<SurfaceMesh>& obstacles = {});

class FrameWriter {
 public:
  /// Writes into `dir` (created on first write), OBJ and/or VTK.
  FrameWriter(std::string dir, bool obj, bool vtk) : dir_(std::move(dir)), obj_(obj), vtk_(vtk) {}

  /// Writes the frame of `step` at time t. Frames with a non-finite position are skipped
  /// (returns false): viewers cannot read NaN.
  bool write(long long step, double t, const std::vector<Vec3>& x, const std::vector<Vec3>& v,
             const std::vector<std::array<int, 3>>& triangles, const std::vector<SurfaceMesh>& obstacles = {});

  long long written() const { return written_; }
  const std::string& dir() const { return dir_; }

 private:
  std::string dir_;
  bool obj_, vtk_;
  long long written_ = 0;
};

}  // namespace tecido::io
