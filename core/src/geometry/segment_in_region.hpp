#pragma once
// Internal: the stretches of a segment that lie on a region's paper (inside the outer loop or on
// its boundary, not strictly inside a hole): where a fold still has paper after a profile.
#include <utility>
#include <vector>

#include "popup/geometry/vectors.hpp"

namespace popup {

/// Parameter intervals [t0, t1] ⊂ [0, 1] of the segment a→b on the region (outer minus holes),
/// boundary within `tol` counted as paper, in order, merged, none shorter than `shortest` mm.
std::vector<std::pair<double, double>> segment_in_region(const Vec2& a, const Vec2& b,
                                                         const Loop2& outer,
                                                         const std::vector<Loop2>& holes,
                                                         double tol, double shortest);

} // namespace popup
