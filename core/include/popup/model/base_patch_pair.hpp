#pragma once
#include <string>

#include "popup/geometry/pose.hpp"

namespace popup {

/// Two patches meeting at a hinge that can carry a mechanism (thesis §5.1.1, Fig 5.6): the card's
/// ground and backdrop at the central fold, a box fold's top, a box side and the base below it.
/// Mechanisms are built in its local frame: y along the hinge from `origin`, z along `up` (the
/// bisector of the opening), x = y × z toward the ground side.
struct BasePatchPair {
    std::string name;
    int ground = -1;   ///< patch id on the local x > 0 side
    int backdrop = -1; ///< patch id on the local x < 0 side
    Vec3 origin = Vec3::Zero();
    Vec3 axis = Vec3::UnitY();
    Vec3 up = Vec3::UnitZ();
    double opening = 3.14159265358979323846; ///< angle between the two patches (radians)
    double length = 0.0;                     ///< usable hinge length from origin (mm)
    double ground_depth = 0.0;   ///< how far the ground patch reaches from the hinge (mm)
    double backdrop_depth = 0.0; ///< same for the backdrop patch

    Vec3 x_axis() const { return axis.cross(up); }
    /// World point of local (x, y, z).
    Vec3 to_world(double x, double y, double z) const
    {
        return origin + x * x_axis() + y * axis + z * up;
    }
    /// Local (x, z) direction of each patch away from the hinge at the design state.
    Vec2 ground_direction() const;
    Vec2 backdrop_direction() const;
    /// World point at distance r from the hinge on the ground (r > 0) or backdrop (r < 0) side,
    /// at y along the hinge.
    Vec3 on_base(double r, double y) const;
};

} // namespace popup
