#pragma once
#include "popup/mechanisms/mechanism.hpp"

namespace popup {

/// Parallel box fold (thesis Fig 4.4, §4.1): sides L and R standing on the host's ground and
/// backdrop at `depth_ground` and `depth_backdrop` from its hinge, top TG and TB meeting over the
/// hinge at `height`, the backbone C from the hinge to the top, and front (FL, FR) and back
/// (BL, BR) panels whose creases pop outward when the card closes. Rectangular section, so the
/// foldability conditions g + l = c + t_g and b + r = c + t_b hold by construction. Offers its top
/// and its two sides as base patch pairs. Needs a host open flat at the design state.
struct BoxFoldParams : Placement1D {
    double depth_ground = 30.0;   ///< g = t_g (mm)
    double depth_backdrop = 30.0; ///< b = t_b (mm)
    double height = 30.0;         ///< c = l = r (mm)
    int panel_pairs = 1;          ///< (FL, FR) and (BL, BR) pairs per end, stacked strips
    bool front = true;            ///< FL, FR (without front and back the box shears)
    bool back = true;             ///< BL, BR
};

/// Closed form of a box fold's section when its host is open at `opening` (equal depths).
struct BoxSection {
    Vec2 top;               ///< top of C, (x, z) in the host's section
    Vec2 side_ground_top;   ///< top edge of L
    Vec2 side_backdrop_top; ///< top edge of R
    Vec2 crease_foot;       ///< foot of the end panels' crease, (x, z)
    double crease_out = 0;  ///< how far that crease stands out of the box's end (mm)
};
BoxSection box_fold_section(const BoxFoldParams& params, double opening);

Result<MechanismParts> add_box_fold(Scaffold& scaffold, const BasePatchPair& host,
                                    const BoxFoldParams& params,
                                    const std::string& name = "BoxFold");

} // namespace popup
