#pragma once
// Internal: where the edges of closed loops cross or touch (CGAL's sweep, exact predicates), for
// the outline checks of validate_scaffold. Its own CGAL translation unit.
#include <optional>
#include <vector>

#include "popup/geometry/vectors.hpp"

namespace popup {

/// A point where two edges of `loops` (each closed) meet other than at a shared loop vertex:
/// a loop crossing itself, or two loops crossing or touching. Nothing when they are apart.
std::optional<Vec2> first_loop_crossing(const std::vector<Loop2>& loops);

} // namespace popup
