#pragma once
// Internal: infinitesimal free motion of a configuration with the base held still.
#include "fold_solver.hpp"
#include "popup/simulation/free_motion.hpp"

namespace popup {

/// The free motions of component `c` alone: how many, and the bodies they move (sorted).
struct ComponentMotion {
    int dimension = 0;
    std::vector<int> moving_bodies;
};
ComponentMotion component_free_motion(const FoldSolver& solver, int c, const Configuration& q);

/// The moving patch ids of `bodies` (sorted body ids), in patch order.
std::vector<int> patches_of_bodies(const Scaffold& scaffold, const BodyGraph& graph,
                                   const std::vector<int>& bodies);

FreeMotion free_motion_of(const Scaffold& scaffold, const FoldSolver& solver,
                          const Configuration& q);

} // namespace popup
