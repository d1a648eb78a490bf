#pragma once
#include <functional>
#include <vector>

#include "popup/geometry/pose.hpp"

namespace popup {

/// Adaptive sampling of a planar path s -> p(s), s in [0, 1] (thesis §6.2 after [dF95]): an
/// interval [a, b] is split at its middle while the polyline through p at a, (3a+b)/4, (a+b)/2,
/// (a+3b)/4, b turns by more than `tolerance_deg` at any inner point (a turn next to a piece
/// shorter than `still` counts as none). Returns ascending s with 0 and 1; a straight path gives
/// {0, 1}. Stops splitting at intervals of 2^-max_depth. docs/MATH.md, Motion targets.
std::vector<double> adaptive_samples(const std::function<Vec2(double)>& path, double tolerance_deg,
                                     double still = 1e-9, int max_depth = 16);

} // namespace popup
