#pragma once
// Internal: infinitesimal free motion of a configuration with the base held still.
#include "fold_solver.hpp"
#include "popup/simulation/check_validity.hpp"

namespace popup {

FreeMotion free_motion_of(const Scaffold& scaffold, const FoldSolver& solver,
                          const Configuration& q);

} // namespace popup
