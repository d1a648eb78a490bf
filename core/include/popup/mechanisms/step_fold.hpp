#pragma once
#include "popup/mechanisms/mechanism.hpp"

namespace popup {

/// Parallelogram step fold (thesis Fig 4.1, mechanism D2): a riser hinged to the host's ground at
/// `run_ground` from the hinge and a tread hinged to its backdrop at `run_backdrop`. The riser is
/// as long as run_backdrop and the tread as run_ground, so the four hinges always form a
/// parallelogram: flat when the host is open flat, erect at 90°.
struct StepFoldParams : Placement1D {
    double run_ground = 30.0;   ///< |S1| (mm)
    double run_backdrop = 20.0; ///< |S2| (mm)
};

/// Closed form: the nose (riser-tread hinge) in the host's section when it is open at `opening`.
Vec2 step_nose(const StepFoldParams& params, double opening);

Result<MechanismParts> add_step_fold(Scaffold& scaffold, const BasePatchPair& host,
                                     const StepFoldParams& params,
                                     const std::string& name = "StepFold");

} // namespace popup
