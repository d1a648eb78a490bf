#pragma once
#include "popup/mechanisms/mechanism.hpp"

namespace popup {

/// Type-2 v-fold (thesis Fig 4.3b, mechanism D1): two triangles O-A-P and O-P-B standing on a
/// base patch pair, hinged to it along O-A and O-B, which make `hinge_angle` with the host's
/// hinge, and to each other along the spine O-P. At the design state P lies in the host's
/// bisecting plane at `spine` from O, `spine_angle` above the host's hinge.
struct VFoldParams {
    double offset = 0.0;                      ///< O along the host hinge (mm)
    double run = 50.0;                        ///< |OA| = |OB| (mm)
    double hinge_angle = 0.78539816339744831; ///< α, radians (thesis: 45°)
    double spine = 55.0;                      ///< |OP| (mm)
    double spine_angle = 1.0471975511965976;  ///< γ, radians
};

/// Closed form: the tip P in the host's local frame (x, y along the hinge from the host's origin,
/// z) when the host, built open at `design_opening`, is open at `opening`.
Vec3 v_fold_tip(const VFoldParams& params, double design_opening, double opening);

/// Closed form: the base patch pair the two wings form along the spine (offered for nesting, a
/// step fold on it makes the thesis's diagonal translation, §4.3.3), posed in the host's local
/// frame when the host, built open at `design_opening`, is open at `opening`. Its origin is O
/// and its axis runs to the tip; its ground is whichever wing lies on its x side.
BasePatchPair v_fold_wings(const VFoldParams& params, double design_opening, double opening);

Result<MechanismParts> add_v_fold(Scaffold& scaffold, const BasePatchPair& host,
                                  const VFoldParams& params, const std::string& name = "VFold");

} // namespace popup
