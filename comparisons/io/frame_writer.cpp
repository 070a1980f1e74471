#include "comparisons/io/frame_writer.h"

#include "comparisons/io/atomic_file.h"

#include <fmt/format.h>

namespace tecido::io {

std::string obj_frame_text(const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles,
                           const std::string& comment) {
  std::string s;
  s.reserve(40 * x.size() + 24 * triangles.size() + 64);
  s += "# " + comment + "\n";
  for (const Vec3& p : x) s += fmt::format("v {:.9g} {:.9g} {:.9g}\n", p.x(), p.y(), p.z());
  for (const auto& t : triangles) s += fmt::format("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1);
  return s;
}

std::string vtk_frame_text(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                           const std::vector<std::array<int, 3>>& triangles, const std::string& title) {
  std::string s;
  s.reserve(80 * x.size() + 24 * triangles.size() + 256);
  s += "# vtk DataFile Version 3.0\n" + title + "\nASCII\nDATASET POLYDATA\n";
  s += fmt::format("POINTS {} double\n", x.size());
  for (const Vec3& p : x) s += fmt::format("{:.9g} {:.9g} {:.9g}\n", p.x(), p.y(), p.z());
  if (!triangles.empty()) {
    s += fmt::format("POLYGONS {} {}\n", triangles.size(), 4 * triangles.size());
    for (const auto& t : triangles) s += fmt::format("3 {} {} {}\n", t[0], t[1], t[2]);
  } else {
    s += fmt::format("VERTICES {} {}\n", x.size(), 2 * x.size());
    for (std::size_t i = 0; i < x.size(); ++i) s += fmt::format("1 {}\n", i);
  }
  if (v.size() == x.size() && !x.empty()) {
    s += fmt::format("POINT_DATA {}\nVECTORS velocity double\n", x.size());
    for (const Vec3& u : v) s += fmt::format("{:.9g} {:.9g} {:.9g}\n", u.x(), u.y(), u.z());
  }
  return s;
}

bool FrameWriter::write(long long step, double t, const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                        const std::vector<std::array<int, 3>>& triangles) {
  for (const Vec3& p : x)
    if (!p.allFinite()) return false;
  const std::string base = fmt::format("{}/frame_{:06d}", dir_, step);
  const std::string label = fmt::format("tecido frame: step {}, t = {:.9g} s", step, t);
  if (obj_) write_file_atomic(base + ".obj", obj_frame_text(x, triangles, label));
  if (vtk_) write_file_atomic(base + ".vtk", vtk_frame_text(x, v, triangles, label));
  ++written_;
  return true;
}

}  // namespace tecido::io
