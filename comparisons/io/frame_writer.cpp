#include "comparisons/io/frame_writer.h"

#include "comparisons/io/atomic_file.h"

#include <fmt/format.h>

namespace tecido::io {

std::string obj_frame_text(const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles,
                           const std::string& comment, const std::vector<SurfaceMesh>& obstacles, int digits) {
  std::string s;
  s.reserve(40 * x.size() + 24 * triangles.size() + 64);
  s += "# " + comment + "\n";
  for (const Vec3& p : x) s += fmt::format("v {:.{}g} {:.{}g} {:.{}g}\n", p.x(), digits, p.y(), digits, p.z(), digits);
  for (const auto& t : triangles) s += fmt::format("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1);
  std::size_t base = x.size();
  for (std::size_t k = 0; k < obstacles.size(); ++k) {
    s += fmt::format("o obstacle_{}\n", k);
    for (const Vec3& p : obstacles[k].vertices)
      s += fmt::format("v {:.{}g} {:.{}g} {:.{}g}\n", p.x(), digits, p.y(), digits, p.z(), digits);
    for (const auto& t : obstacles[k].triangles)
      s += fmt::format("f {} {} {}\n", base + t[0] + 1, base + t[1] + 1, base + t[2] + 1);
    base += obstacles[k].vertices.size();
  }
  return s;
}

std::string vtk_frame_text(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                           const std::vector<std::array<int, 3>>& triangles, const std::string& title,
                           const std::vector<SurfaceMesh>& obstacles) {
  std::size_t n_points = x.size(), n_polys = triangles.size();
  for (const SurfaceMesh& m : obstacles) n_points += m.vertices.size(), n_polys += m.triangles.size();
  std::string s;
  s.reserve(80 * n_points + 24 * n_polys + 256);
  s += "# vtk DataFile Version 3.0\n" + title + "\nASCII\nDATASET POLYDATA\n";
  s += fmt::format("POINTS {} double\n", n_points);
  for (const Vec3& p : x) s += fmt::format("{:.9g} {:.9g} {:.9g}\n", p.x(), p.y(), p.z());
  for (const SurfaceMesh& m : obstacles)
    for (const Vec3& p : m.vertices) s += fmt::format("{:.9g} {:.9g} {:.9g}\n", p.x(), p.y(), p.z());
  std::size_t n_vertices = 0;  // VERTICES cells (a scene without triangles is a point cloud)
  if (triangles.empty()) {
    n_vertices = x.size();
    s += fmt::format("VERTICES {} {}\n", x.size(), 2 * x.size());
    for (std::size_t i = 0; i < x.size(); ++i) s += fmt::format("1 {}\n", i);
  }
  if (n_polys > 0) {
    s += fmt::format("POLYGONS {} {}\n", n_polys, 4 * n_polys);
    for (const auto& t : triangles) s += fmt::format("3 {} {} {}\n", t[0], t[1], t[2]);
    std::size_t base = x.size();
    for (const SurfaceMesh& m : obstacles) {
      for (const auto& t : m.triangles) s += fmt::format("3 {} {} {}\n", base + t[0], base + t[1], base + t[2]);
      base += m.vertices.size();
    }
  }
  if (v.size() == x.size() && !x.empty()) {
    s += fmt::format("POINT_DATA {}\nVECTORS velocity double\n", n_points);
    for (const Vec3& u : v) s += fmt::format("{:.9g} {:.9g} {:.9g}\n", u.x(), u.y(), u.z());
    for (std::size_t k = x.size(); k < n_points; ++k) s += "0 0 0\n";
  }
  if (!obstacles.empty()) {
    // Cells in file order: VERTICES, then POLYGONS (the scene's triangles, then each obstacle's).
    s += fmt::format("CELL_DATA {}\nSCALARS body int 1\nLOOKUP_TABLE default\n", n_vertices + n_polys);
    for (std::size_t c = 0; c < n_vertices + triangles.size(); ++c) s += "0\n";
    for (std::size_t k = 0; k < obstacles.size(); ++k)
      for (std::size_t c = 0; c < obstacles[k].triangles.size(); ++c) s += fmt::format("{}\n", k + 1);
  }
  return s;
}

bool FrameWriter::write(long long step, double t, const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                        const std::vector<std::array<int, 3>>& triangles, const std::vector<SurfaceMesh>& obstacles) {
  for (const Vec3& p : x)
    if (!p.allFinite()) return false;
  const std::string base = fmt::format("{}/frame_{:06d}", dir_, step);
  const std::string label = fmt::format("tecido frame: step {}, t = {:.9g} s", step, t);
  if (obj_) write_file_atomic(base + ".obj", obj_frame_text(x, triangles, label, obstacles));
  if (vtk_) write_file_atomic(base + ".vtk", vtk_frame_text(x, v, triangles, label, obstacles));
  ++written_;
  return true;
}

}  // namespace tecido::io
