#include "snap_onto_lines.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "polygon_2d.hpp"

namespace popup {

namespace {

double cross(const Vec2& a, const Vec2& b)
{
    return a.x() * b.y() - a.y() * b.x();
}

Vec2 foot(const Vec2& q, const std::array<Vec2, 2>& line)
{
    const Vec2 d = line[1] - line[0];
    return line[0] + (q - line[0]).dot(d) / d.squaredNorm() * d;
}

// Where the lines through two segments cross, unless they are (nearly) parallel: then either
// foot is as good, and the caller takes the first.
std::optional<Vec2> crossing(const std::array<Vec2, 2>& a, const std::array<Vec2, 2>& b)
{
    const Vec2 da = a[1] - a[0], db = b[1] - b[0];
    const double sine = cross(da, db) / (da.norm() * db.norm());
    if (std::abs(sine) < 1e-9)
        return std::nullopt;
    return a[0] + cross(b[0] - a[0], db) / cross(da, db) * da;
}

} // namespace

void snap_onto_lines(Loop2& loop, const SnapTargets& targets, double reach)
{
    for (Vec2& q : loop) {
        const Vec2* corner = nullptr;
        for (const Vec2& c : targets.corners)
            if ((c - q).norm() <= reach && (!corner || (c - q).norm() < (*corner - q).norm()))
                corner = &c;
        if (corner) {
            q = *corner;
            continue;
        }
        std::vector<const std::array<Vec2, 2>*> near;
        for (const auto& line : targets.lines)
            if ((line[1] - line[0]).norm() > 0.0 &&
                distance_to_segment(q, line[0], line[1]) <= reach)
                near.push_back(&line);
        if (near.empty())
            continue;
        std::optional<Vec2> at;
        for (size_t i = 0; i < near.size() && !at; ++i)
            for (size_t j = i + 1; j < near.size() && !at; ++j)
                if (const auto x = crossing(*near[i], *near[j]); x && (*x - q).norm() <= 2 * reach)
                    at = x;
        q = at ? *at : foot(q, *near.front());
    }
    // Two vertices a few nanometres apart may have gone to the same corner: keep one.
    loop.erase(std::unique(loop.begin(), loop.end()), loop.end());
    while (loop.size() > 1 && loop.front() == loop.back())
        loop.pop_back();
}

} // namespace popup
