#pragma once
// The paper a planned mechanism puts where its prism stood, and how far samples lie from it: the
// mapping's score (docs/MATH.md, "Mapping by distance"). Closed forms of the generators at the
// design state, so the mapping needs no scaffold.
#include <vector>

#include "popup/fitting/prism_types.hpp"
#include "popup/mechanisms/designed_mechanism.hpp"

namespace popup {

/// A convex planar polygon in a host's coordinates, the generators' local frame: x across the
/// hinge (a prism's s; along the page on a right-angle host), y along it (a), z up (t).
using HostPolygon = std::vector<Vec3>;

/// The patches `m` (a box, step, tent or v-fold as map_mechanisms plans them) has at the design
/// state on `host`: the card open flat (180°) on a flat host, the box's side at 90° for a step.
/// Box: backbone C, sides L and R, tops TG and TB, and its front and back panels (each end as one
/// rectangle); tent: both slopes, meeting at the generator's apex (tent_apex); v-fold: both
/// wings O-A-P and O-P-B; step: riser and tread. Another kind is std::invalid_argument.
std::vector<HostPolygon> design_patches(const DesignedMechanism& m, const PrismHost& host);

/// Distance (mm) from `q` to the nearest point of the nearest of `patches`; 1e300 for none.
double distance_to_patches(const Vec3& q, const std::vector<HostPolygon>& patches);

/// `p` (card frame) in `host`'s coordinates (x across, y along the hinge, z up).
Vec3 host_coordinates(const PrismHost& host, const Vec3& p);

} // namespace popup
