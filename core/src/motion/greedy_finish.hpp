#pragma once
#include "design_types.hpp"

namespace popup::motion {

/// Greedy finish (compound moves the search rarely makes in one step): each moving chain,
/// heaviest first, that the search left printed, on a floating layer or off its own mapping
/// takes back its own mapping's mechanism when that hits no moving mechanism (the still
/// parts' floating layers it would hit are printed instead) and eq 6.5 drops; then each
/// printed still part takes its floating layer where that is free and cheaper.
///
/// Parts left printed on the page then leave the mechanisms (the report's stationary parts
/// without a floating layer), with their reasons.
void greedy_finish(MotionDesign& design);

} // namespace popup::motion
