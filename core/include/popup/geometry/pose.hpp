#pragma once
#include <Eigen/Geometry>

#include "popup/geometry/vectors.hpp"

namespace popup {

/// Rigid motion x -> rotation * x + translation, mapping design-state world coordinates (mm) to
/// world coordinates at some fold angle.
struct Pose {
    Mat3 rotation = Mat3::Identity();
    Vec3 translation = Vec3::Zero();

    Vec3 apply(const Vec3& x) const { return rotation * x + translation; }
    Pose then(const Pose& outer) const
    {
        return {outer.rotation * rotation, outer.rotation * translation + outer.translation};
    }
};

/// The rigid motion that undoes p.
inline Pose inverse(const Pose& p)
{
    return {p.rotation.transpose(), -(p.rotation.transpose() * p.translation)};
}

/// Rotation by `angle` (radians) about the unit axis `axis` (Rodrigues).
Mat3 axis_angle(const Vec3& axis, double angle);

/// Rotation exp([w]x) for a rotation vector w.
Mat3 rotation_exp(const Vec3& w);

/// Rotation vector w with rotation_exp(w) == r.
Vec3 rotation_log(const Mat3& r);

} // namespace popup
