#include "fold_sides.hpp"

#include <algorithm>
#include <cmath>

namespace popup::sheets {

namespace {

constexpr double side_step = 1e-4; // mm beside a fold line: a point in the face on either side

// Where the segment a–b crosses the cut outline's loops, as fractions of it (sorted, with 0
// and 1): between two neighbours the line is either all on paper or all in a slot.
std::vector<double> crossings(const Region& outline, const Vec2& a, const Vec2& b)
{
    std::vector<double> t{0.0, 1.0};
    const Vec2 d = b - a;
    auto cross = [](const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); };
    auto add = [&](const Loop2& loop) {
        for (size_t i = 0; i < loop.size(); ++i) {
            const Vec2 &p = loop[i], e = loop[(i + 1) % loop.size()] - p;
            const double den = cross(d, e);
            if (std::abs(den) < 1e-12)
                continue;
            const double u = cross(p - a, d) / den, s = cross(p - a, e) / den;
            if (u >= 0 && u <= 1 && s > 0 && s < 1)
                t.push_back(s);
        }
    };
    add(outline.outer);
    for (const Loop2& h : outline.holes)
        add(h);
    std::sort(t.begin(), t.end());
    return t;
}

} // namespace

// The faces on either side of a drawn fold line.
// (A slit's slot may cut the line anywhere, leaving paper only in bridges near its ends: the
// middle, then the middle of each stretch between the line's crossings with the cut, until one
// has paper on both sides. Fixed fractions missed the 5 mm bridges of a 56 mm extruding patch's
// slot, found on a BVH from elsewhere.)
std::pair<int, int> sides(const DrawnPiece& piece, const DrawnFold& f)
{
    const Vec2 along = (f.to - f.from).normalized();
    const Vec2 left(-along.y(), along.x());
    std::vector<double> probes{0.5};
    const std::vector<double> t = crossings(piece.outline, f.from, f.to);
    for (size_t i = 0; i + 1 < t.size(); ++i)
        probes.push_back((t[i] + t[i + 1]) / 2);
    std::pair<int, int> found{-1, -1};
    for (double p : probes) {
        const Vec2 at = f.from + p * (f.to - f.from);
        found = {piece.face_at(at + side_step * left), piece.face_at(at - side_step * left)};
        if (found.first >= 0 && found.second >= 0)
            break;
    }
    return found;
}

} // namespace popup::sheets
