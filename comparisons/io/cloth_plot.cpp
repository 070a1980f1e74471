#include "comparisons/io/cloth_plot.h"

#include "comparisons/io/atomic_file.h"
#include "comparisons/io/gnuplot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace tecido::io {

bool plot_cloth_frames(const std::string& dir, const std::string& name, const std::string& title,
                       const std::vector<PlotFrame>& frames, const std::vector<std::array<int, 3>>& triangles,
                       const std::optional<Vec3>& gravity, std::string* why) {
  std::vector<const PlotFrame*> shown;
  for (const auto& f : frames) {
    bool finite = !f.x.empty();
    for (const Vec3& p : f.x) finite = finite && p.allFinite();
    if (finite) shown.push_back(&f);
  }
  if (shown.empty()) {
    if (why) *why = "no finite frame to plot";
    return false;
  }
  // Vertical axis: the one most opposed to gravity; the plot's (a, b, up) is a cyclic (so
  // right-handed) permutation of (x, y, z).
  int up = 2;
  if (gravity && gravity->norm() > 0.0) {
    Vec3 g = gravity->cwiseAbs();
    g.maxCoeff(&up);
  }
  const int ia = (up + 1) % 3, ib = (up + 2) % 3;
  const char* names = "xyz";
  const bool flip = gravity && gravity->norm() > 0.0 && (*gravity)[up] > 0.0;  // "up" opposes gravity
  auto coord = [&](const Vec3& p) {
    return std::array<double, 3>{p[ia], flip ? -p[ib] : p[ib], flip ? -p[up] : p[up]};
  };

  // Unique mesh edges (or points).
  std::set<std::pair<int, int>> edge_set;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) edge_set.insert({std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])});
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  std::string dat;
  for (const PlotFrame* f : shown) {
    dat += fmt::format("# step {} t = {:.6g} s\n", f->step, f->time);
    for (const Vec3& p : f->x) {
      const auto c = coord(p);
      for (int d = 0; d < 3; ++d) {
        lo[d] = std::min(lo[d], c[d]);
        hi[d] = std::max(hi[d], c[d]);
      }
    }
    if (edge_set.empty()) {
      for (const Vec3& p : f->x) {
        const auto c = coord(p);
        dat += fmt::format("{:.7g} {:.7g} {:.7g}\n", c[0], c[1], c[2]);
      }
    } else {
      for (const auto& [i, j] : edge_set) {
        const auto a = coord(f->x[i]), b = coord(f->x[j]);
        dat += fmt::format("{:.7g} {:.7g} {:.7g}\n{:.7g} {:.7g} {:.7g}\n\n", a[0], a[1], a[2], b[0], b[1], b[2]);
      }
    }
    dat += "\n\n";
  }
  write_file_atomic(dir + "/" + name + ".dat", dat);

  double span = 0.0;
  for (int d = 0; d < 3; ++d) span = std::max(span, hi[d] - lo[d]);
  if (!(span > 0.0)) span = 1.0;
  const int n = static_cast<int>(shown.size());
  const int cols = n <= 2 ? n : 2, rows = (n + cols - 1) / cols;
  std::string gp;
  // noenhanced: file names keep their underscores; single quotes doubled inside gnuplot strings.
  std::string safe_title;
  for (char ch : title) safe_title += ch == '\'' ? std::string("''") : std::string(1, ch);
  gp += fmt::format("set terminal svg size {},{} dynamic noenhanced font 'Helvetica,11' background rgb 'white'\n", 520 * cols,
                    460 * rows + 40);
  gp += fmt::format("set output '{}.svg'\n", name);
  gp += fmt::format("set multiplot layout {},{} title '{}'\n", rows, cols, safe_title);
  gp += "set view equal xyz\nset view 65, 35\nset xyplane 0\nunset key\nset tics font ',8'\n";
  const std::string sign = flip ? "-" : "";
  gp += fmt::format("set xlabel '{}'\nset ylabel '{}{}'\nset zlabel '{}{}'\n", names[ia], sign, names[ib], sign, names[up]);
  for (int d = 0; d < 3; ++d) {
    const double mid = 0.5 * (lo[d] + hi[d]);
    gp += fmt::format("set {}range [{:.6g}:{:.6g}]\n", "xyz"[d], mid - 0.55 * span, mid + 0.55 * span);
  }
  for (int k = 0; k < n; ++k) {
    gp += fmt::format("set title 'step {}, t = {:.3g} s'\n", shown[k]->step, shown[k]->time);
    gp += fmt::format("splot '{}.dat' index {} with {} lc rgb '#1f4e8c' lw 0.6\n", name, k,
                      edge_set.empty() ? "points pt 7 ps 0.4" : "lines");
  }
  gp += "unset multiplot\n";
  if (!gnuplot_available()) {
    write_file_atomic(dir + "/" + name + ".gp", gp);
    if (why) *why = "gnuplot not found on PATH; skipped " + name + ".svg (the data and script are in " + dir + ")";
    return false;
  }
  if (!run_gnuplot(dir, name, gp)) {
    if (why) *why = "gnuplot failed on " + dir + "/" + name + ".gp";
    return false;
  }
  return true;
}

}  // namespace tecido::io
