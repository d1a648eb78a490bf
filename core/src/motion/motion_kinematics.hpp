#pragma once
#include <cmath>

#include "motion_mechanism.hpp"
#include "popup/geometry/pose.hpp"

namespace popup::motion {

/// The mechanism's moving point (the end effector it carries) in the card frame when the card
/// is open at theta: the rotation arm's tip, the v-box's front top corner, the extruding patch's
/// far edge (middle), the step's nose on the v-fold's wings (middle), a platform point. Closed
/// forms of the library (rotation_arm_tip, v_box_front_corner, horizontal_translation_tip,
/// v_fold_wings + step_nose); its (x, y) is what the viewer sees (thesis §6: the projection on
/// the card plane).
Vec3 mechanism_point(const MotionMechanism& m, double theta);

/// Where a rotation arm carries a part placed at `open` (card x, y) on its arm's wing when the
/// card is open: the point of the wing's plane there, moved rigidly with the wing O-S-P to fold
/// angle theta (a merged arm carries each chain's part in its own place; docs/DESIGN.md). At the
/// tip's open point it is mechanism_point.
Vec3 rotation_carried_point(const MotionMechanism& m, const Vec2& open, double theta);

/// The ground page's and the backdrop's unit directions in a section across the fold at fold
/// angle theta, and a section point (x, z) at y along the fold.
inline Vec2 ground_dir(double theta)
{
    return {std::sin(theta / 2), std::cos(theta / 2)};
}
inline Vec2 backdrop_dir(double theta)
{
    return {-std::sin(theta / 2), std::cos(theta / 2)};
}
inline Vec3 at(const Vec2& section, double y)
{
    return {section.x(), y, section.y()};
}

// The rotation arm's points in the card frame at fold angle theta: O on its hinge, the wings'
// outer corners S (the arm's wing O-S-P) and S', R on the spine, the tip P.
struct ArmInCard {
    Vec3 O, S, Sb, R, P;
};

ArmInCard arm_in_card(const MotionMechanism& m, double theta);

} // namespace popup::motion
