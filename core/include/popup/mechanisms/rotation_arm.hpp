#pragma once
#include "popup/mechanisms/floating_layer.hpp"
#include "popup/mechanisms/mechanism.hpp"

namespace popup {

/// Rotation (thesis §4.3.4, Fig 4.15): a v-fold lying flat on the host at the design state, its
/// spine O-R along the host hinge, whose ground wing O-S-P is extended past the spine by an arm:
/// R lies on S-P with |PR| = `arm`. Closing, the spine pops up and P swings through the
/// bisecting plane: P_x = −h sin δ and P_y follows thesis eq 4.10 (docs/MATH.md, Rotation). On a
/// host open less than flat (a floating layer's side pair) it is built on the same branch at the
/// host's design opening.
struct RotationArmParams {
    double offset = 0.0; ///< O along the host hinge (mm)
    double spine = 40.0; ///< l = |OQ| = |OR| (mm)
    double run = 30.0;   ///< w = |QS|, the wing's reach from the hinge (mm)
    double arm = 20.0;   ///< h = |PR|, at most l²/w so the arm stays above the backdrop (mm)
};

/// The arm's points relative to O (in the host's local frame, y along the hinge) when the host
/// is open at `opening`: S and S' (the wings' far corners), R (the spine's tip) and P (the tip).
struct RotationArmPoints {
    Vec3 S, Sb, R, P;
};
RotationArmPoints rotation_arm_points(const RotationArmParams& params, double opening);

/// Closed form: P in the host's local frame (x, y along the hinge from the host's origin, z)
/// when the host is open at `opening`. It holds for any design opening of the host: the arm is
/// built on this branch (the wings popped off the host) at the host's design opening.
Vec3 rotation_arm_tip(const RotationArmParams& params, double opening);

/// Closed form of the thesis's off-fold rotation (§4.3.4, last paragraph): an arm standing on
/// the side pair `side` of a floating layer `layer`, in the frame of the layer's host (the card
/// frame when the layer stands on the central fold) at host angle `angle`. The side pair opens
/// at angle/2 (docs/MATH.md, "A rotation arm on a floating layer's side").
Vec3 rotation_arm_tip_on_layer_side(const RotationArmParams& arm, const FloatingLayerParams& layer,
                                    LayerSide side, double angle);

/// Builds the arm on any host open more than 0° and at most 180° at the design state: flat on a
/// flat host, from the closed form at the host's opening otherwise (a floating layer's side).
Result<MechanismParts> add_rotation_arm(Scaffold& scaffold, const BasePatchPair& host,
                                        const RotationArmParams& params,
                                        const std::string& name = "RotationArm");

} // namespace popup
