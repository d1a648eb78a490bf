#pragma once
#include "motion_mechanism.hpp"

// Each kind's mechanism from its named fields, the library's params it builds with, and what
// follows from them (an off-fold rotation's layer, the mechanism's height).

namespace popup::motion {

/// mm kept inside every generator range, so the build succeeds.
constexpr double build_margin = 1.0;

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

/// A mechanism of the kind with its params' defaults (a rotation on the fold).
MotionMechanism default_mechanism(MotionKind kind);
/// Each kind's mechanism from its fields (motion_mechanism.hpp says what they are).
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

/// The library's params each kind is built with.
/// The arm as built on its host: off the fold it starts at 0 on its layer's side pair.
RotationArmParams rotation_params(const MotionMechanism& m);
VBoxFoldParams vertical_params(const MotionMechanism& m);
HorizontalTranslationParams horizontal_params(const MotionMechanism& m);
VFoldParams diagonal_v_fold(const MotionMechanism& m);  ///< the diagonal's v-fold
StepFoldParams diagonal_step(const MotionMechanism& m); ///< the step fold on its wings
FloatingLayerParams layer_params(const MotionMechanism& m);
/// The side pair of its layer an off-fold rotation stands on (the sign of its hinge).
LayerSide rotation_side(const MotionMechanism& m);

/// Where the mechanism starts along the fold (a rotation's arm's, or off the fold its layer's,
/// start; a diagonal's v-fold's), to read or to move it.
double fold_offset(const MotionMechanism& m);
double& fold_offset(MotionMechanism& m);

} // namespace popup::motion
