#include "comparisons/suites/bench/folding_cloth.h"

#include "comparisons/io/atomic_file.h"
#include "comparisons/io/frame_writer.h"
#include "core/scene/cloth_builder.h"

#include <fmt/format.h>

#include <cmath>

namespace tecido::suites::bench {

namespace {
/// The rest position (u, v, 0) on the cloth folded with flap height h, lowered by `drop`.
Vec3 folded_point(const Vec3& rest, double h, double drop) {
  const double r = 0.5 * h, u = rest.x(), v = rest.y();
  const double ripple = 0.03 * std::sin(9.0 * u + 1.0) * std::sin(7.0 * v);
  if (u <= 0.5) return Vec3(u, v, ripple - drop);
  const double a = (u - 0.5) / r;
  if (a < M_PI) return Vec3(0.5 + r * std::sin(a), v, r - r * std::cos(a) + ripple - drop);
  return Vec3(0.5 - (u - 0.5 - M_PI * r), v, h - ripple - drop);
}

std::vector<Vec3> folded(const std::vector<Vec3>& rest, double h, double drop) {
  std::vector<Vec3> x;
  x.reserve(rest.size());
  for (const Vec3& p : rest) x.push_back(folded_point(p, h, drop));
  return x;
}
}  // namespace

FoldingStep folding_cloth_step(int n, bool gentle) {
  Scene s;
  append_cloth(s, unit_square_cloth(n));
  FoldingStep st;
  st.rest = s.particles.x;
  st.triangles = s.triangles;
  st.x0 = folded(st.rest, gentle ? 0.0225 : 0.04, 0.0);
  st.x1 = folded(st.rest, 0.02, gentle ? 0.002 : 0.01);
  return st;
}

FoldingFiles write_folding_step(const FoldingStep& step, int n, const std::string& dir) {
  const FoldingFiles f{fmt::format("{}/fold_{}_t0.obj", dir, n), fmt::format("{}/fold_{}_t1.obj", dir, n)};
  const std::string about = fmt::format("{0} x {0} cloth folding onto itself (comparisons/suites/bench/folding_cloth.h), ", n);
  io::write_file_atomic(f.start, io::obj_frame_text(step.x0, step.triangles, about + "start frame", {}, 17));
  io::write_file_atomic(f.end, io::obj_frame_text(step.x1, step.triangles, about + "end frame", {}, 17));
  return f;
}

}  // namespace tecido::suites::bench
