#include "sheet_labels.hpp"

#include <algorithm>
#include <cmath>

#include "../geometry/polygon_2d.hpp"

namespace popup::sheets {

namespace {

constexpr int grid = 24; // candidate points per side of a patch's bounding box

// Distance from q to the nearest cut line, crease or glue area edge of the piece.
double clearance(const LocalPiece& piece, const Vec2& q)
{
    double d = 1e300;
    for (const Region& r : piece.cut_nominal) {
        d = std::min(d, distance_to_boundary(r.outer, q));
        for (const Loop2& h : r.holes)
            d = std::min(d, distance_to_boundary(h, q));
    }
    for (const FoldLine& f : piece.folds)
        d = std::min(d, distance_to_segment(q, f.from, f.to));
    for (const GlueArea& g : piece.glue)
        d = std::min(d, distance_to_boundary(g.polygon, q));
    return d;
}

bool on_paper(const LocalPiece& piece, const Vec2& q)
{
    for (const GlueArea& g : piece.glue)
        if (point_in_polygon(g.polygon, q))
            return false;
    for (const Region& r : piece.cut_nominal)
        if (point_in_polygon(r.outer, q)) {
            for (const Loop2& h : r.holes)
                if (point_in_polygon(h, q))
                    return false;
            return true;
        }
    return false;
}

Vec2 mean(const Loop2& loop)
{
    Vec2 sum = Vec2::Zero();
    for (const Vec2& p : loop)
        sum += p;
    return sum / double(loop.size());
}

// Text direction along a crease.
double reading_angle(const Vec2& from, const Vec2& to)
{
    return upright(std::atan2(to.y() - from.y(), to.x() - from.x()) * 180.0 / M_PI);
}

} // namespace

double upright(double degrees)
{
    double angle = std::remainder(degrees, 360.0);
    if (angle > 90.0 + 1e-9)
        angle -= 180.0;
    else if (angle <= -90.0 + 1e-9)
        angle += 180.0;
    return angle;
}

void add_labels(LocalPiece& piece, const std::string& piece_id, bool fold_hints)
{
    Vec2 best = mean(piece.flat.outlines.front());
    double room = -1.0;
    for (const Loop2& outline : piece.flat.outlines) {
        Eigen::AlignedBox2d box;
        for (const Vec2& p : outline)
            box.extend(p);
        for (int i = 1; i < grid; ++i)
            for (int j = 1; j < grid; ++j) {
                const Vec2 q =
                    box.min() + Vec2(box.sizes().x() * i / grid, box.sizes().y() * j / grid);
                if (!on_paper(piece, q))
                    continue;
                const double c = clearance(piece, q);
                if (c > room + 1e-9) {
                    room = c;
                    best = q;
                }
            }
    }
    piece.labels.push_back({piece_id, "piece", best, std::clamp(0.6 * room, 1.5, 8.0), 0.0});
    for (const GlueTab& t : piece.tabs)
        piece.labels.push_back({t.code, "tab", mean(t.polygon),
                                std::clamp(0.45 * t.width, 1.0, 5.0),
                                reading_angle(t.polygon[0], t.polygon[1])});
    for (const GlueArea& g : piece.glue) {
        const double depth = distance_to_segment(g.polygon[2], g.polygon[0], g.polygon[1]);
        // A tab glued to the paper's other face: the mark is printed here, the glue goes there.
        const std::string text = g.front ? g.code : g.code + " (back)";
        piece.labels.push_back({text, "glue", mean(g.polygon), std::clamp(0.3 * depth, 1.0, 5.0),
                                reading_angle(g.polygon[0], g.polygon[1])});
    }
    if (!fold_hints)
        return;
    for (const FoldLine& f : piece.folds) {
        const Vec2 along = (f.to - f.from).normalized();
        const Vec2 beside = 0.5 * (f.from + f.to) + 2.5 * left_normal(along);
        piece.labels.push_back({f.direction == FoldDirection::mountain ? "M" : "V", "fold", beside,
                                2.5, reading_angle(f.from, f.to)});
    }
}

} // namespace popup::sheets
