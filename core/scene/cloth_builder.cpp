#include "core/scene/cloth_builder.h"

namespace tecido {

void append_cloth(Scene& scene, const ClothGridSpec& spec) {
  const int first = static_cast<int>(scene.particles.size());
  const int rows = spec.rows, cols = spec.cols;
  scene.cloth = spec;
  scene.cloth_first_particle = first;
  auto node = [&](int r, int c) { return cloth_node(spec, first, r, c); };

  std::vector<Vec3> pos(static_cast<std::size_t>(rows) * cols);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      pos[static_cast<std::size_t>(r) * cols + c] = spec.origin + (c * spec.spacing) * spec.axis_u + (r * spec.spacing) * spec.axis_v;

  // Triangles, and mass by area.
  std::vector<double> mass(pos.size(), 0.0);
  std::vector<std::array<int, 3>> local;
  local.reserve(static_cast<std::size_t>(2) * (rows - 1) * (cols - 1));
  for (int r = 0; r + 1 < rows; ++r) {
    for (int c = 0; c + 1 < cols; ++c) {
      const int a = r * cols + c, b = r * cols + c + 1, d = (r + 1) * cols + c + 1, e = (r + 1) * cols + c;
      local.push_back({a, b, d});
      local.push_back({a, d, e});
    }
  }
  double total_area = 0.0;
  std::vector<double> area(local.size());
  for (std::size_t t = 0; t < local.size(); ++t) {
    const auto& tri = local[t];
    area[t] = 0.5 * (pos[tri[1]] - pos[tri[0]]).cross(pos[tri[2]] - pos[tri[0]]).norm();
    total_area += area[t];
  }
  for (std::size_t t = 0; t < local.size(); ++t) {
    const double share = spec.total_mass * area[t] / total_area / 3.0;
    for (int k = 0; k < 3; ++k) mass[local[t][k]] += share;
  }

  std::vector<std::uint8_t> pinned(pos.size(), 0);
  for (const auto& p : spec.pins) pinned[static_cast<std::size_t>(p[0]) * cols + p[1]] = 1;
  for (std::size_t i = 0; i < pos.size(); ++i)
    scene.particles.add(pos[i], Vec3::Zero(), mass[i], spec.elasticity, pinned[i] != 0);

  for (const auto& tri : local) scene.triangles.push_back({first + tri[0], first + tri[1], first + tri[2]});

  // Springs: offsets (dr, dc) for horizontal, vertical, diagonal, anti-diagonal, scaled by the
  // connection's reach (1 = type B, 2 = type A).
  auto add_family = [&](int reach, double stiffness) {
    if (stiffness <= 0.0) return;
    const int offsets[4][2] = {{0, 1}, {1, 0}, {1, 1}, {1, -1}};
    for (const auto& o : offsets) {
      const int dr = o[0] * reach, dc = o[1] * reach;
      for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < cols; ++c) {
          const int r2 = r + dr, c2 = c + dc;
          if (r2 < 0 || r2 >= rows || c2 < 0 || c2 >= cols) continue;
          const int i = node(r, c), j = node(r2, c2);
          scene.forces.springs.push_back(
              Spring{i, j, stiffness, (scene.particles.x[j] - scene.particles.x[i]).norm(), spec.damping});
        }
      }
    }
  };
  add_family(1, spec.stiffness_b);
  add_family(2, spec.stiffness_a);
}

}  // namespace tecido
