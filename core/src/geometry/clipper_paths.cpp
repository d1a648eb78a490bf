#include "clipper_paths.hpp"

#include <cmath>

namespace popup {

ClipperLib::IntPoint to_int_point(const Vec2& p)
{
    return {static_cast<ClipperLib::cInt>(std::llround(p.x() * clipper_scale)),
            static_cast<ClipperLib::cInt>(std::llround(p.y() * clipper_scale))};
}

Vec2 to_vec2(const ClipperLib::IntPoint& p)
{
    return {static_cast<double>(p.X) / clipper_scale, static_cast<double>(p.Y) / clipper_scale};
}

ClipperLib::Path to_path(const Loop2& loop)
{
    ClipperLib::Path path;
    path.reserve(loop.size());
    for (const Vec2& p : loop)
        path.push_back(to_int_point(p));
    return path;
}

Loop2 to_loop(const ClipperLib::Path& path)
{
    Loop2 loop;
    loop.reserve(path.size());
    for (const ClipperLib::IntPoint& p : path)
        loop.push_back(to_vec2(p));
    return loop;
}

ClipperLib::Paths counter_clockwise_paths(const std::vector<Loop2>& loops)
{
    ClipperLib::Paths paths;
    for (const Loop2& loop : loops) {
        ClipperLib::Path path = to_path(loop);
        if (!ClipperLib::Orientation(path))
            ClipperLib::ReversePath(path);
        paths.push_back(std::move(path));
    }
    return paths;
}

double path_area(const ClipperLib::Path& path)
{
    return ClipperLib::Area(path) / (clipper_scale * clipper_scale);
}

} // namespace popup
