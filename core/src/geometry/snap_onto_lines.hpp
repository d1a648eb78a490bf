#pragma once
// Internal: puts the vertices of a clipped outline back onto the exact corners and lines it was
// clipped against. Clipper answers on its integer grid, so a vertex that belongs on a patch's
// edge or fold comes back a fraction of a grid unit off it (docs/DESIGN.md, "Profiles keep their
// folds exact").
#include <array>
#include <vector>

#include "popup/geometry/vectors.hpp"

namespace popup {

struct SnapTargets {
    std::vector<Vec2> corners;              ///< points a nearby vertex becomes exactly
    std::vector<std::array<Vec2, 2>> lines; ///< segments a nearby vertex is put onto
};

/// Each vertex within `reach` of a corner becomes that corner; else, within `reach` of two
/// segments that cross, their crossing; else, within `reach` of one segment, its foot on it.
/// Vertices farther from every target stay where they are; vertices that land on the same point
/// as the one before them are dropped.
void snap_onto_lines(Loop2& loop, const SnapTargets& targets, double reach);

} // namespace popup
