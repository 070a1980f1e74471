#pragma once
/// Basic geometric types shared by the whole engine: double precision, SI units,
/// right-handed coordinates.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>

namespace tecido {

using Vec3 = Eigen::Vector3d;
using Vec2 = Eigen::Vector2d;

/// A triangle as three corner positions, in order.
using Triangle = std::array<Vec3, 3>;

}  // namespace tecido
