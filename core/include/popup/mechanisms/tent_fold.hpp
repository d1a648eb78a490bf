#pragma once
#include "popup/mechanisms/mechanism.hpp"

namespace popup {

/// Tent fold standing on a base patch pair (thesis Fig 4.2), symmetric or not. Two slopes hinged
/// to the host's patches at distances `foot` and `foot_backdrop` from its hinge, meeting at the
/// apex. The backdrop slope is derived so the tent folds flat (|T1| + |T3| = |T2| + |T4|):
/// slope_backdrop = foot + slope − foot_backdrop.
struct TentFoldParams : Placement1D {
    double foot = 30.0;          ///< |T1|, on the host's ground (mm)
    double foot_backdrop = 30.0; ///< |T2|, on the host's backdrop (mm)
    double slope = 40.0;         ///< |T3|, the ground-side slope (mm)
};

double tent_backdrop_slope(const TentFoldParams& params);

/// Closed form: the apex in the host's section (x, z) when the host is open at `opening`.
Vec2 tent_apex(const TentFoldParams& params, double opening);

/// Adds the tent to the scaffold, or nothing with errors naming the parameter and its range.
Result<MechanismParts> add_tent_fold(Scaffold& scaffold, const BasePatchPair& host,
                                     const TentFoldParams& params,
                                     const std::string& name = "TentFold");

} // namespace popup
