#pragma once
#include "chain_mapping.hpp"
#include "popup/model/card.hpp"

namespace popup::motion {

/// How far across the fold (|x|, mm) any paper of `card` can be seen at fold angle theta: every
/// patch stays between the pages and within the card's depth of the fold, so its projection on
/// the card plane is at most depth · sin(θ/2) from the fold (docs/MATH.md, "The reach floor").
double card_reach(const CardParams& card, double theta);

/// The lowest eq 6.6 error (mm) any mechanism on `card` could have on t: the RMS over t's samples
/// of how far the target lies beyond card_reach across the fold. A chain far from the fold whose
/// motion starts early cannot be followed while the card is nearly closed, whatever carries it.
double reach_floor_mm(const ChainTarget& t, const CardParams& card);

} // namespace popup::motion
