#pragma once
/// Distances between two sets of node positions in the same numbering.
#include "core/geometry/types.h"

#include <vector>

namespace tecido::suites::tradeoff {

/// RMS over nodes of |a_i - b_i| [m]; NaN when empty or of different sizes.
double rms_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b);

/// Max over nodes and coordinates of |a_i - b_i| (0 when bit-identical and finite; +inf when a
/// coordinate is NaN or the sizes differ).
double max_abs_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b);

}  // namespace tecido::suites::tradeoff
