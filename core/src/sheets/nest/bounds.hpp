#pragma once
// Axis-aligned rectangles in Clipper units, y up (Clipper's own IntRect has y down).
#include <algorithm>

#include "../../geometry/clipper_paths.hpp"

namespace popup::nest_detail {

struct Bounds {
    ClipperLib::cInt left = 0;
    ClipperLib::cInt bottom = 0;
    ClipperLib::cInt right = 0;
    ClipperLib::cInt top = 0;
    ClipperLib::cInt width() const { return right - left; }
    ClipperLib::cInt height() const { return top - bottom; }
};

/// The bounding box of a non-empty path.
inline Bounds bounds_of(const ClipperLib::Path& path)
{
    Bounds box{path.front().X, path.front().Y, path.front().X, path.front().Y};
    for (const ClipperLib::IntPoint& p : path) {
        box.left = std::min(box.left, p.X);
        box.bottom = std::min(box.bottom, p.Y);
        box.right = std::max(box.right, p.X);
        box.top = std::max(box.top, p.Y);
    }
    return box;
}

} // namespace popup::nest_detail
