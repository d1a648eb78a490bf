#pragma once
// Internal: the fold sweep of simulate_fold on a scaffold validated already, for the validity
// check, which builds the body graph and the solver once for the sweep and the checks after it.
#include <vector>

#include "popup/model/result.hpp"
#include "popup/simulation/fold_state.hpp"

namespace popup {

class FoldSolver;

/// The angles must be in 0..π.
Result<FoldSweep> simulate_validated(const FoldSolver& solver, const std::vector<double>& angles);

} // namespace popup
