#pragma once
#include <vector>

#include "popup/model/result.hpp"
#include "popup/model/scaffold.hpp"
#include "popup/simulation/fold_state.hpp"

namespace popup {

/// Drives the base patches from the design angle to each requested angle (radians, 0..π) by
/// damped Newton with continuation, keeping glued patches rigid and hinges closed. Folds that are
/// flat at the design state follow their FoldDirection. Angles the motion cannot reach are left
/// out and reported.
Result<FoldSweep> simulate_fold(const Scaffold& scaffold, const std::vector<double>& angles,
                                const SimulationOptions& options = {});

/// Continues the motion from a state already on the branch (a cached one, say) to each requested
/// angle: the cheap way to follow a dragged fold angle. From the design state it is
/// simulate_fold.
Result<FoldSweep> continue_fold(const Scaffold& scaffold, const FoldState& from,
                                const std::vector<double>& angles,
                                const SimulationOptions& options = {});

/// World coordinates of a patch's outer loop in a given state.
Loop3 posed_outline(const Patch& patch, const Pose& pose);

} // namespace popup
