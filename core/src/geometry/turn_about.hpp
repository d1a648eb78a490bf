#pragma once
#include "popup/geometry/pose.hpp"

namespace popup {

/// Rotation by `angle` (radians) about the line through `point` along the unit `axis`: how a
/// piece turns about a fold, unfolding it (sheets) or folding it back (verify's assembly).
inline Pose turn_about(const Vec3& point, const Vec3& axis, double angle)
{
    Pose p;
    p.rotation = axis_angle(axis, angle);
    p.translation = point - p.rotation * point;
    return p;
}

} // namespace popup
