#pragma once
// Conversions between the core's millimetre loops and Clipper's integer paths. Clipper works on
// integers; one unit is a nanometre, far below any cutter's resolution, and sheets up to a metre
// stay within its fast 30-bit range.
#include <polyclipping/clipper.hpp>

#include "popup/geometry/vectors.hpp"

namespace popup {

constexpr double clipper_scale = 1e6; ///< Clipper units per millimetre

ClipperLib::IntPoint to_int_point(const Vec2& p);
Vec2 to_vec2(const ClipperLib::IntPoint& p);
ClipperLib::Path to_path(const Loop2& loop);
Loop2 to_loop(const ClipperLib::Path& path);
/// The loops as paths, each turned counter-clockwise: filled non-zero, winding then does not
/// matter.
ClipperLib::Paths counter_clockwise_paths(const std::vector<Loop2>& loops);
/// Area in mm² (signed: positive for counter-clockwise).
double path_area(const ClipperLib::Path& path);

} // namespace popup
