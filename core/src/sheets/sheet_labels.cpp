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

// Where a glue area's code goes: its middle, unless another glue area of the piece (on the
// paper's other face) covers that point; then the point of the area nearest the middle that
// stands clear of the others by half the text's width, so that no two codes print on top of each
// other (the reader gives a code to the smallest area holding it). Without such room, the point
// deepest both inside the area and outside the others: the reader needs the code's position
// there, never on an edge (two crowded areas on a small support of a rotation arm's layer had
// both codes put on their own edges, and the round trip found neither).
Vec2 glue_label_position(const LocalPiece& piece, size_t index, double width)
{
    const GlueArea& g = piece.glue[index];
    auto clear_by = [&](const Vec2& q) {
        double nearest = 1e300;
        for (size_t k = 0; k < piece.glue.size(); ++k)
            if (k != index) {
                const Loop2& other = piece.glue[k].polygon;
                if (point_in_polygon(other, q))
                    return -1.0;
                nearest = std::min(nearest, distance_to_boundary(other, q));
            }
        return nearest;
    };
    const Vec2 middle = mean(g.polygon);
    if (clear_by(middle) >= 0.0)
        return middle;
    // Points over the area: the quad (crease 0-1, far edge 2-3) sampled bilinearly.
    constexpr int samples = 32;
    const Vec2 &p0 = g.polygon[0], &p1 = g.polygon[1], &p2 = g.polygon[2], &p3 = g.polygon[3];
    Vec2 best = middle;
    double best_room = -1.0, best_shift = 1e300;
    bool best_enough = false;
    for (int i = 1; i < samples; ++i)
        for (int j = 1; j < samples; ++j) {
            const double u = double(i) / samples, v = double(j) / samples;
            const Vec2 q = (1 - v) * (p0 + u * (p1 - p0)) + v * (p3 + u * (p2 - p3));
            if (!point_in_polygon(g.polygon, q))
                continue;
            const double inside = distance_to_boundary(g.polygon, q), clear = clear_by(q);
            if (clear < 0.0)
                continue;
            const bool enough = clear >= 0.5 * width;
            const double room = std::min(inside, clear), shift = (q - middle).norm();
            if ((enough && (!best_enough || shift < best_shift)) ||
                (!enough && !best_enough && room > best_room)) {
                best = q;
                best_room = room;
                best_shift = shift;
                best_enough = enough;
            }
        }
    return best;
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
    for (size_t k = 0; k < piece.glue.size(); ++k) {
        const GlueArea& g = piece.glue[k];
        const double depth = distance_to_segment(g.polygon[2], g.polygon[0], g.polygon[1]);
        // A tab glued to the paper's other face: the mark is printed here, the glue goes there.
        const std::string text = g.front ? g.code : g.code + " (back)";
        const double height = std::clamp(0.3 * depth, 1.0, 5.0);
        // About 0.6 of its height per character.
        const double width = 0.6 * height * double(text.size());
        piece.labels.push_back({text, "glue", glue_label_position(piece, k, width), height,
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
