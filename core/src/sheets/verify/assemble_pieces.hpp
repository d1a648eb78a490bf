#pragma once
// Phase 4 of verify_sheets: the card put together from the drawing alone.
#include <map>

#include "verification.hpp"

namespace popup::sheets {

/// Re-makes the card from the drawing alone: the card's piece folded along its drawn lines from
/// the ground, then each later piece brought by a tab onto the glue area its code names and
/// folded in turn. `from_sheet` gets every patch's pose from the drawing into the design's frame.
/// False, with a finding, when a piece or patch cannot be reached that way.
bool assemble_pieces(Verification& v, std::map<int, Pose>& from_sheet);

} // namespace popup::sheets
