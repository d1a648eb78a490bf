#pragma once
// Quarter turns, the only rotations the packers use: exact on Clipper's integer points.
#include "../../geometry/clipper_paths.hpp"

namespace popup::nest_detail {

/// p turned counter-clockwise about the origin by `quarter_turns` × 90° (0 to 3).
inline ClipperLib::IntPoint quarter_turn(const ClipperLib::IntPoint& p, int quarter_turns)
{
    switch (quarter_turns) {
    case 1:
        return {-p.Y, p.X};
    case 2:
        return {-p.X, -p.Y};
    case 3:
        return {p.Y, -p.X};
    default:
        return p;
    }
}

inline Vec2 quarter_turn(const Vec2& p, int quarter_turns)
{
    switch (quarter_turns) {
    case 1:
        return {-p.y(), p.x()};
    case 2:
        return -p;
    case 3:
        return {p.y(), -p.x()};
    default:
        return p;
    }
}

} // namespace popup::nest_detail
