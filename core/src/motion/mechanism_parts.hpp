#pragma once
#include <vector>

#include "motion_mechanism.hpp"
#include "popup/geometry/pose.hpp"

namespace popup::motion {

/// One rigid convex piece of a mechanism's paper at some fold angle: every point of the piece
/// is a convex combination of `vertices` (a patch, or the part of a patch on one side of a
/// crease line through it), listed along its outline (the vertical's top halves end with both
/// roots of their back corner). `side` says which side of the card's bisecting plane x = 0 the
/// piece keeps to at every fold angle (derived per kind in docs/MATH.md, "Tight collision
/// volumes"): +1 never at x < 0 (the ground's half), −1 never at x > 0, 0 either. Pieces on
/// opposite sides can touch only on that plane, so they never cross.
struct MechanismPart {
    std::vector<Vec3> vertices;
    int side = 0;
};

/// The mechanism's patches at theta in closed form, one entry per piece, in an order and count
/// that do not depend on theta (for the collision volumes). The vertical's top halves carry both
/// roots of their back corner (conservative).
std::vector<MechanismPart> mechanism_parts(const MotionMechanism& m, double theta);
/// The same into `out`, reusing its storage (no allocation once it has held them).
void mechanism_parts(const MotionMechanism& m, double theta, std::vector<MechanismPart>& out);

/// Every patch vertex of the mechanism at theta, in closed form: the pieces' vertices together
/// (a vertex shared by two pieces appears once per piece).
std::vector<Vec3> mechanism_vertices(const MotionMechanism& m, double theta);

} // namespace popup::motion
