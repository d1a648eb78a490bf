#pragma once
// The central fold of an A4 card (210 along the fold, 148 to either side) as the host the bulk
// box and the bulk stack stand on, in the card frame: origin 0, axis +y, across +x, up +z.
#include "popup/fitting/prism_types.hpp"

namespace popup::testing {

inline PrismHost card_hinge()
{
    PrismHost card;
    card.name = "central fold";
    card.length = 210;
    card.across_min = -148;
    card.across_max = 148;
    return card;
}

} // namespace popup::testing
