#pragma once
// The few polygon set operations the layout needs, on millimetre loops through Clipper.
#include <vector>

#include "popup/model/patch.hpp"

namespace popup::sheets {

/// Area (mm²) common to two sets of loops (each set filled non-zero after orienting its loops
/// counter-clockwise, so winding does not matter).
double overlap_area(const std::vector<Loop2>& a, const std::vector<Loop2>& b);

/// Area (mm²) of `a` outside the region (outer minus holes).
double area_outside(const Loop2& a, const Loop2& outer, const std::vector<Loop2>& holes);

double loop_area(const Loop2& loop); ///< signed, counter-clockwise positive

} // namespace popup::sheets
