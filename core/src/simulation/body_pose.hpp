#pragma once
// Internal: the unknowns of the fold solver. Every body has a pose x -> R (x - c) + p, c its
// design-state centre (BodyGraph::center), so that the design state is R = I, p = c.
#include <vector>

#include "popup/geometry/pose.hpp"

namespace popup {

struct BodyPose {
    Mat3 rotation = Mat3::Identity();
    Vec3 position = Vec3::Zero();
};
using Configuration = std::vector<BodyPose>;

} // namespace popup
