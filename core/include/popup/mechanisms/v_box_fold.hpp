#pragma once
#include "popup/mechanisms/mechanism.hpp"

namespace popup {

/// Type-1 v-fold, the v-box (thesis Fig 4.3a): four walls standing on a rhombus whose diagonal
/// lies on the host's hinge, closed by a two-triangle top. The front walls FL and FR are hinged
/// to the host's ground and backdrop and form a v-fold with them; the back walls BL and BR hang
/// from the front walls and each other; the top halves TG and TB are hinged to FL and FR and to
/// each other along the top diagonal (TB is NOT joined to BR, nor TG to BL: the top must fold).
/// The thesis fixes the walls at 45° to the hinge; `wall_angle` generalises it.
struct VBoxFoldParams {
    double offset = 0.0;                     ///< front corner along the host hinge (mm)
    double side = 40.0;                      ///< wall length along the host (mm)
    double height = 30.0;                    ///< wall height at the design state (mm)
    double wall_angle = 0.78539816339744831; ///< β between each wall and the hinge (radians)
    bool back = true; ///< false: the thesis's triangular half (FL, FR, TG, TB) without BL, BR
};

/// Closed form: the front top corner F' (where FL, FR, TG and TB meet) in the host's local frame
/// when the host is open at `opening`: the tip of the front walls' v-fold, whose spine stands
/// vertical at 180° (docs/MATH.md, Vertical translation).
Vec3 v_box_front_corner(const VBoxFoldParams& params, double opening);

/// Vertical translation (thesis §4.3.2): the triangular half v-box, two v-folds (the front walls
/// on the host, the top halves on the walls) joined along the front spine; the top's front corner
/// moves along the host hinge, P_y = −h sin α cos δ / √(cos²α + sin²α cos²δ), P_x = 0.
Result<MechanismParts> add_vertical_translation(Scaffold& scaffold, const BasePatchPair& host,
                                                VBoxFoldParams params,
                                                const std::string& name = "VerticalTranslation");

Result<MechanismParts> add_v_box_fold(Scaffold& scaffold, const BasePatchPair& host,
                                      const VBoxFoldParams& params,
                                      const std::string& name = "VBoxFold");

} // namespace popup
