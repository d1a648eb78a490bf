#pragma once
// The free motion a fold state leaves when the base is held still (the stability check's test).
#include <vector>

#include "popup/model/scaffold.hpp"
#include "popup/simulation/fold_state.hpp"

namespace popup {

/// Dimension of the free motion left when the base is held still at one state, and the ids of
/// the patches that take part in it.
struct FreeMotion {
    int dimension = 0;
    std::vector<int> moving_patches;
};
FreeMotion free_motion(const Scaffold& scaffold, const FoldState& state);

} // namespace popup
