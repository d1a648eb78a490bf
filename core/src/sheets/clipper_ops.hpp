#pragma once
// The few polygon set operations the layout needs, on millimetre loops through Clipper.
#include <vector>

#include <polyclipping/clipper.hpp>

#include "popup/sheets/sheet_set.hpp"

namespace popup::sheets {

/// Area (mm²) common to two sets of loops (each set filled non-zero after orienting its loops
/// counter-clockwise, so winding does not matter).
double overlap_area(const std::vector<Loop2>& a, const std::vector<Loop2>& b);

/// Area (mm²) of `a` outside the region (outer minus holes).
double area_outside(const Loop2& a, const Loop2& outer, const std::vector<Loop2>& holes);

double loop_area(const Loop2& loop); ///< signed, counter-clockwise positive

/// Every outline of a Clipper result with its holes; islands inside holes are regions of their
/// own. Appended to `regions`.
void collect_regions(const ClipperLib::PolyNode& node, std::vector<Region>& regions);

} // namespace popup::sheets
