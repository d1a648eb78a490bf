#pragma once
#include <string>

#include "motion_mechanism.hpp"
#include "popup/model/card.hpp"

namespace popup::motion {

/// Empty when the generators accept the parameters on `card`; otherwise why not (the first
/// failed range). Mirrors the add_* checks, with a margin so the simulator's build succeeds, and
/// refuses glued creases shorter than shortest_crease().
std::string infeasibility(const MotionMechanism& m, const CardParams& card);

/// infeasibility(m, card).empty(), without writing the reason (the search asks per move).
bool feasible(const MotionMechanism& m, const CardParams& card);

/// False for a diagonal whose v-fold wings, one piece unfolded about their spine with a glue
/// tab on each side, do not fit the card's open sheet (W × 2D, which PopUp sizes to the paper);
/// true for every other kind.
bool diagonal_wings_fit(const MotionMechanism& m, const CardParams& card);

} // namespace popup::motion
