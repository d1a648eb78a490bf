#include "popup/geometry/pose.hpp"

#include <cmath>

namespace popup {

Mat3 axis_angle(const Vec3& axis, double angle)
{
    return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

Mat3 rotation_exp(const Vec3& w)
{
    const double angle = w.norm();
    if (angle < 1e-300)
        return Mat3::Identity();
    return Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
}

Vec3 rotation_log(const Mat3& r)
{
    const Eigen::AngleAxisd aa(r);
    return aa.axis() * aa.angle();
}

} // namespace popup
