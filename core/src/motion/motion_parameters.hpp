#pragma once
#include "motion_mechanism.hpp"
#include "popup/mechanisms/floating_layer.hpp"
#include "popup/mechanisms/horizontal_translation.hpp"
#include "popup/mechanisms/rotation_arm.hpp"
#include "popup/mechanisms/step_fold.hpp"
#include "popup/mechanisms/v_box_fold.hpp"
#include "popup/mechanisms/v_fold.hpp"

// The layout of MotionMechanism::p (motion_mechanism.hpp), in this one place: per kind, the
// library's params fields (mm and radians) in order.
// - vertical   (add_vertical_translation): offset, side, height, wall_angle
// - diagonal   (add_v_fold, spine standing, + add_step_fold on its wings): offset, run,
//               hinge_angle, spine, step_offset, step_width, run_ground, run_backdrop
// - horizontal (add_horizontal_translation): offset, width, run_ground, run_backdrop, reach
// - rotation   (add_rotation_arm): offset, spine, run, arm, hinge — hinge 0: on the central
//               fold; ±s: on the side pair (+ ground, − backdrop) of a floating layer with
//               supports s from the fold, as wide as the spine, from offset, its height
//               rotation_layer_height (thesis §4.3.4, last paragraph: a rotation off the fold)
// - stationary (add_floating_layer): offset, width, height, support, overhang, anchor (the
//               platform point, across the fold, that carries the part)
// Nothing else reads or writes p[] by position, but for stepping every entry alike (the
// annealing, the polish, the finite check).

namespace popup::motion {

/// mm kept inside every generator range, so the build succeeds.
constexpr double build_margin = 1.0;

int parameter_count(MotionKind kind);
ParameterInfo parameter_info(MotionKind kind, int index);
/// The parameters that shape this mechanism: a rotation on the central fold (hinge 0) has no
/// layer, so its hinge is not stepped (a small hinge is no layer either: it is infeasible).
int active_parameter_count(const MotionMechanism& m);

/// A rotation standing on a floating layer's side pair (hinge != 0).
bool rotation_off_fold(const MotionMechanism& m);
/// The floating layer an off-fold rotation stands on: supports |hinge|, width spine, from
/// offset, no overhang, height rotation_layer_height.
FloatingLayerParams rotation_layer(const MotionMechanism& m);
/// The layer's height: the lowest the arm's checks allow (Run < height, Arm <= height) with
/// 1 mm to spare, at least the shortest glued crease. The tip's path does not depend on it.
double rotation_layer_height(double run, double arm);

/// Height of the mechanism's carrying patch above the card at 180° (mm): H of eq 6.7.
double mechanism_height(const MotionMechanism& m);

/// The shortest crease the default cutting sheets can glue (their narrowest tab, ≈ 11.1 mm), as
/// FitOptions::min_part_mm: infeasibility refuses a mechanism with a shorter glued crease, which
/// nobody could assemble (popup animate's sheets failed on such designs).
double shortest_crease();

/// Each kind's p[] from its fields, in the order the unpackers read them (the entries past the
/// kind's count are 0).
MotionMechanism rotation_mechanism(double offset, double spine, double run, double arm,
                                   double hinge = 0.0);
MotionMechanism vertical_mechanism(double offset, double side, double height, double wall_angle);
MotionMechanism horizontal_mechanism(double offset, double width, double run_ground,
                                     double run_backdrop, double reach);
MotionMechanism diagonal_mechanism(double offset, double run, double hinge_angle, double spine,
                                   double step_offset, double step_width, double run_ground,
                                   double run_backdrop);
MotionMechanism layer_mechanism(double offset, double width, double height, double support,
                                double overhang, double anchor);

/// The library's params of each kind, unpacked from p[].
RotationArmParams rotation_params(const MotionMechanism& m);
VBoxFoldParams vertical_params(const MotionMechanism& m);
HorizontalTranslationParams horizontal_params(const MotionMechanism& m);
VFoldParams diagonal_v_fold(const MotionMechanism& m);  ///< the diagonal's v-fold
StepFoldParams diagonal_step(const MotionMechanism& m); ///< the step fold on its wings
FloatingLayerParams layer_params(const MotionMechanism& m);
/// The side pair of its layer an off-fold rotation stands on (the sign of its hinge).
LayerSide rotation_side(const MotionMechanism& m);

/// Where the mechanism starts along the fold (p[0] of every kind; a rotation's arm's, or off the
/// fold its layer's, start), to read or to move it.
inline double fold_offset(const MotionMechanism& m)
{
    return m.p[0];
}
inline double& fold_offset(MotionMechanism& m)
{
    return m.p[0];
}
/// The diagonal's v-fold run, to shorten it.
inline double& diagonal_run(MotionMechanism& m)
{
    return m.p[1];
}
/// A rotation's hinge: 0 on the central fold, ±s on its layer's side pair.
inline double rotation_hinge(const MotionMechanism& m)
{
    return m.p[4];
}
/// The platform point (across the fold) that carries a floating layer's part.
inline double layer_anchor(const MotionMechanism& m)
{
    return m.p[5];
}

} // namespace popup::motion
