#pragma once
/// The work limit of a run (comparisons/io/limits.h, kDefaultMaxWork): a scene's memory is
/// bounded by its counts, but its time is steps x the work of one step, and "steps" is a number
/// a file can make as large as it likes. A run is accepted when steps x elements per step stays
/// within the limit (the user raises it knowingly, `tecido run --max-work N`), checked before the
/// first step.
#include "core/scene/scene.h"

#include <string>

namespace tecido::io {

/// The fixed cost of a step, in elements (measured: one particle above one plane costs about 20
/// times a spring's share of a cloth step).
constexpr double kStepOverhead = 16.0;
/// A triangle of a self-colliding cloth costs about 10 spring updates per detection (measured on
/// the seed's scene; a crumpled cloth, with many more contact pairs, costs more).
constexpr double kTriangleWeight = 10.0;

/// What one step costs, in elements: kStepOverhead + particles + springs + particles x planes +
/// kTriangleWeight x triangles (with self-collision).
double elements_per_step(const Scene& scene);

/// Empty when `steps` steps of `scene` fit in `max_work` element-steps; otherwise the problem,
/// e.g. "1000000000 steps x 1010 elements per step = 1.01e+12 element-steps, more than the work
/// limit of 1e+11 per run (raise it with --max-work)".
std::string work_limit_problem(const Scene& scene, long long steps, double max_work);

}  // namespace tecido::io
