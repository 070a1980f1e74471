#include "comparisons/io/work_limit.h"

#include <sstream>

namespace tecido::io {

double elements_per_step(const Scene& scene) {
  const auto n = static_cast<double>(scene.particles.size());
  double e = kStepOverhead + n + static_cast<double>(scene.forces.springs.size()) + n * static_cast<double>(scene.planes.size());
  if (scene.self_collision) e += kTriangleWeight * static_cast<double>(scene.triangles.size());
  return e;
}

std::string work_limit_problem(const Scene& scene, long long steps, double max_work) {
  const double per_step = elements_per_step(scene);
  const double work = per_step * static_cast<double>(steps);
  if (work <= max_work) return "";
  std::ostringstream s;
  s << steps << " steps x " << per_step << " elements per step = " << work
    << " element-steps, more than the work limit of " << max_work << " per run (raise it with --max-work)";
  return s.str();
}

}  // namespace tecido::io
