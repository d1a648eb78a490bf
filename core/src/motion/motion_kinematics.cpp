// GCC 16 (Debian sid) reports -Warray-bounds inside Eigen 5's vectorised loads once the 3 x 2 QR
// of rotation_carried_point is inlined (a two-double load at a 3-vector's tail, in bounds). The
// warning is placed in Eigen's own header, so only a pragma ahead of its inclusion reaches it:
// this translation unit only.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 16
#pragma GCC diagnostic ignored "-Warray-bounds"
#endif
#include "motion_kinematics.hpp"

#include "motion_parameters.hpp"

namespace popup::motion {

Vec3 mechanism_point(const MotionMechanism& m, double theta)
{
    switch (m.kind()) {
    case MotionKind::rotation:
        if (rotation_off_fold(m))
            return rotation_arm_tip_on_layer_side(rotation_params(m), rotation_layer(m),
                                                  rotation_side(m), theta);
        return rotation_arm_tip(rotation_params(m), theta);
    case MotionKind::vertical:
        return v_box_front_corner(vertical_params(m), theta);
    case MotionKind::horizontal: {
        const HorizontalTranslationParams h = horizontal_params(m);
        return at(horizontal_translation_tip(h, theta), h.offset + h.width / 2);
    }
    case MotionKind::diagonal: {
        const StepFoldParams s = diagonal_step(m);
        const BasePatchPair wings = v_fold_wings(diagonal_v_fold(m), M_PI, theta);
        const Vec2 nose =
            s.run_ground * ground_dir(wings.opening) + s.run_backdrop * backdrop_dir(wings.opening);
        return wings.to_world(nose.x(), s.offset + s.width / 2, nose.y());
    }
    case MotionKind::stationary: {
        const FloatingLayerParams f = layer_params(m);
        const double anchor = m.stationary().anchor;
        const Vec2 along = anchor >= 0 ? ground_dir(theta) : backdrop_dir(theta);
        return at(Vec2(0, f.height) + std::abs(anchor) * along, f.offset + f.width / 2);
    }
    }
    return Vec3::Zero();
}

ArmInCard arm_in_card(const MotionMechanism& m, double theta)
{
    const RotationArmParams r = rotation_params(m);
    BasePatchPair host; // the central fold: the card frame
    host.opening = theta;
    if (rotation_off_fold(m))
        host = floating_layer_side(rotation_layer(m), rotation_side(m), theta);
    const RotationArmPoints a = rotation_arm_points(r, host.opening);
    auto world = [&](const Vec3& q) { return host.to_world(q.x(), r.offset + q.y(), q.z()); };
    return {world(Vec3::Zero()), world(a.S), world(a.Sb), world(a.R), world(a.P)};
}

Vec3 rotation_carried_point(const MotionMechanism& m, const Vec2& open, double theta)
{
    // The wing O-S-P is rigid: a point of its plane keeps its coordinates along S − O and P − O.
    // Open, the point is the one of the plane above `open` (the wing lies on the page there).
    const ArmInCard a = arm_in_card(m, M_PI);
    const Vec3 e1 = a.S - a.O, e2 = a.P - a.O, n = e1.cross(e2);
    if (!(std::abs(n.z()) > 1e-9 * n.norm()))
        return mechanism_point(m, theta); // the wing stands edge-on to the page: at its tip
    const Vec3 q(open.x(), open.y(),
                 a.O.z() - (n.x() * (open.x() - a.O.x()) + n.y() * (open.y() - a.O.y())) / n.z());
    Eigen::Matrix<double, 3, 2> basis;
    basis << e1, e2;
    const Vec2 c = basis.colPivHouseholderQr().solve(q - a.O);
    const ArmInCard b = arm_in_card(m, theta);
    return b.O + c.x() * (b.S - b.O) + c.y() * (b.P - b.O);
}

} // namespace popup::motion
