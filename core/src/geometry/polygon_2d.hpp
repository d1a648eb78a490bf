#pragma once
// Plain 2D polygon helpers shared by validation and the enclosure check (no CGAL, no OCCT).
#include "popup/geometry/vectors.hpp"

namespace popup {

/// Distance from q to the segment ab.
double distance_to_segment(const Vec2& q, const Vec2& a, const Vec2& b);

/// Distance from q to the polygon's boundary.
double distance_to_boundary(const Loop2& polygon, const Vec2& q);

/// Even-odd inside test.
bool point_in_polygon(const Loop2& polygon, const Vec2& q);

/// Inside, or within `tol` of the boundary when tol > 0; strictly inside by more than -tol when
/// tol < 0.
bool point_in_polygon_or_near(const Loop2& polygon, const Vec2& q, double tol);

} // namespace popup
