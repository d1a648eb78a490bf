#pragma once
// The vocabulary every layer speaks: points, directions and polygons in millimetres.
#include <vector>

#include <Eigen/Core>

namespace popup {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

using Loop3 = std::vector<Vec3>; ///< a closed polygon in space, last vertex joined to the first
using Loop2 = std::vector<Vec2>; ///< a closed polygon in a plane

} // namespace popup
