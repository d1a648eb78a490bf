#pragma once
#include "design_types.hpp"

namespace popup::motion {

/// Conflicts the search resolved by moving a chain off its own mechanism onto one that
/// misses its path by more than remap_bound (of the diagonal) beyond its own: the chain is
/// not resolved (thesis §6.4.3), so when its own mechanism collides with another slot's it
/// becomes stationary instead, and the reason names the other chain.
/// Alike chains may share the other's patch instead (thesis §6.4.3, merging) when that costs less.
void release_far_remaps(MotionDesign& design);

/// Collisions the search could not resolve: the lighter mechanism of the deepest pair
/// becomes stationary (thesis §6.4.3 move 4), until none is left.
void repair_collisions(MotionDesign& design);

} // namespace popup::motion
