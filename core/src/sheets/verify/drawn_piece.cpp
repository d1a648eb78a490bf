#include "drawn_piece.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <sstream>

#include "../../geometry/clipper_paths.hpp"
#include "../../geometry/loop_crossings.hpp"
#include "../../geometry/polygon_2d.hpp"
#include "../clipper_ops.hpp"

namespace popup::sheets {

namespace {

using ClipperLib::Paths;

constexpr double miter_limit = 8.0;  // as the writer's kerf offset, so the offset undoes it
constexpr double slit_half = 1e-5;   // mm: half the width of the cut that splits faces at a fold
constexpr double snap_to_end = 1e-3; // mm: a face corner this near a fold's end is that end
constexpr double max_reach = 1.0;    // mm: a fold ending this short of the cut is carried to it
const std::regex piece_label("P[1-9][0-9]*");

std::string where(const Vec2& p)
{
    std::ostringstream s;
    s.precision(6);
    s << "(" << p.x() << ", " << p.y() << ")";
    return s.str();
}

Paths region_paths(const Region& r)
{
    Paths paths{to_path(r.outer)};
    for (const Loop2& h : r.holes)
        paths.push_back(to_path(h));
    return paths;
}

// The cut loops, filled even-odd (an outline and its holes), moved in by half the kerf.
std::vector<Region> nominal_regions(const std::vector<Loop2>& cut, double kerf)
{
    ClipperLib::Clipper merge;
    Paths loops;
    for (const Loop2& l : cut)
        loops.push_back(to_path(l));
    merge.AddPaths(loops, ClipperLib::ptSubject, true);
    Paths merged;
    merge.Execute(ClipperLib::ctUnion, merged, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd);
    ClipperLib::ClipperOffset offsetter(miter_limit);
    offsetter.AddPaths(merged, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
    ClipperLib::PolyTree tree;
    offsetter.Execute(tree, -0.5 * kerf * clipper_scale);
    std::vector<Region> regions;
    collect_regions(tree, regions);
    return regions;
}

// The region cut along every fold line by a hairline, the faces' corners put back on the lines.
std::vector<Region> split_faces(const Region& outline, const std::vector<DrawnFold>& folds)
{
    // How far past an end the line must go to reach the cut: a fold drawn a little short of
    // the outline (a file rounded by another program, a kerf undone) still splits the paper.
    // Ends on another fold (a junction) stay where they are.
    auto reach = [&](const Vec2& end, const Vec2& out, const DrawnFold& self) {
        for (const DrawnFold& g : folds)
            if (&g != &self && distance_to_segment(end, g.from, g.to) < 1e-4)
                return 2 * slit_half;
        double nearest = 1e300;
        auto hit = [&](const Loop2& loop) {
            for (size_t i = 0; i < loop.size(); ++i) {
                const Vec2 &p = loop[i], e = loop[(i + 1) % loop.size()] - loop[i];
                const double den = out.x() * e.y() - out.y() * e.x();
                if (std::abs(den) < 1e-12)
                    continue;
                const Vec2 w = p - end;
                const double t = (w.x() * e.y() - w.y() * e.x()) / den;
                const double u = (w.x() * out.y() - w.y() * out.x()) / den;
                if (t >= -slit_half && u >= 0.0 && u <= 1.0)
                    nearest = std::min(nearest, t);
            }
        };
        hit(outline.outer);
        for (const Loop2& h : outline.holes)
            hit(h);
        return nearest <= max_reach ? std::max(nearest, 0.0) + 2 * slit_half : 2 * slit_half;
    };
    Paths cuts;
    for (const DrawnFold& f : folds) {
        const Vec2 along = (f.to - f.from).normalized();
        const Vec2 side(-along.y() * slit_half, along.x() * slit_half);
        const Vec2 a = f.from - along * reach(f.from, -along, f);
        const Vec2 b = f.to + along * reach(f.to, along, f);
        cuts.push_back(to_path({a - side, b - side, b + side, a + side}));
    }
    ClipperLib::Clipper clipper;
    clipper.AddPaths(region_paths(outline), ClipperLib::ptSubject, true);
    clipper.AddPaths(cuts, ClipperLib::ptClip, true);
    ClipperLib::PolyTree tree;
    clipper.Execute(ClipperLib::ctDifference, tree, ClipperLib::pftEvenOdd, ClipperLib::pftNonZero);
    std::vector<Region> faces;
    collect_regions(tree, faces);
    auto snap = [&](Vec2& p) {
        for (const DrawnFold& f : folds) {
            if (distance_to_segment(p, f.from, f.to) > 3 * slit_half)
                continue;
            if ((p - f.from).norm() <= snap_to_end)
                p = f.from;
            else if ((p - f.to).norm() <= snap_to_end)
                p = f.to;
            else {
                const Vec2 d = (f.to - f.from).normalized();
                p = f.from + d * d.dot(p - f.from);
            }
            return;
        }
    };
    for (Region& face : faces) {
        std::for_each(face.outer.begin(), face.outer.end(), snap);
        for (Loop2& h : face.holes)
            std::for_each(h.begin(), h.end(), snap);
        // Corners snapped onto one fold end leave a repeated point: drop it.
        auto dedupe = [](Loop2& loop) {
            Loop2 out;
            for (const Vec2& p : loop)
                if (out.empty() || (p - out.back()).norm() > 1e-9)
                    out.push_back(p);
            while (out.size() > 1 && (out.front() - out.back()).norm() <= 1e-9)
                out.pop_back();
            loop = out;
        };
        dedupe(face.outer);
        for (Loop2& h : face.holes)
            dedupe(h);
    }
    return faces;
}

Vec2 mean(const Loop2& loop)
{
    Vec2 sum = Vec2::Zero();
    for (const Vec2& p : loop)
        sum += p;
    return sum / double(std::max<size_t>(loop.size(), 1));
}

constexpr double far_coordinate = 1e6; // mm: a kilometre; nothing on paper lies beyond

bool finite_loop(const Loop2& loop)
{
    return std::all_of(loop.begin(), loop.end(), [](const Vec2& p) {
        return p.allFinite() && p.cwiseAbs().maxCoeff() <= far_coordinate;
    });
}

} // namespace

bool inside_region(const Region& region, const Vec2& q)
{
    if (!point_in_polygon(region.outer, q))
        return false;
    return std::none_of(region.holes.begin(), region.holes.end(),
                        [&](const Loop2& h) { return point_in_polygon(h, q); });
}

Vec2 interior_point(const Region& region)
{
    // The middle of the widest run inside the region along a few horizontal lines.
    double low = 1e300, high = -1e300;
    for (const Vec2& p : region.outer) {
        low = std::min(low, p.y());
        high = std::max(high, p.y());
    }
    Vec2 best = mean(region.outer);
    double widest = -1.0;
    for (int k = 1; k < 8; ++k) {
        const double y = low + (high - low) * k / 8.0;
        std::vector<double> xs;
        auto crossings = [&](const Loop2& loop) {
            for (size_t i = 0; i < loop.size(); ++i) {
                const Vec2& a = loop[i];
                const Vec2& b = loop[(i + 1) % loop.size()];
                if ((a.y() > y) != (b.y() > y))
                    xs.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
            }
        };
        crossings(region.outer);
        for (const Loop2& h : region.holes)
            crossings(h);
        std::sort(xs.begin(), xs.end());
        for (size_t i = 0; i + 1 < xs.size(); i += 2)
            if (xs[i + 1] - xs[i] > widest) {
                widest = xs[i + 1] - xs[i];
                best = {0.5 * (xs[i] + xs[i + 1]), y};
            }
    }
    return best;
}

int DrawnPiece::face_at(const Vec2& q) const
{
    for (size_t i = 0; i < faces.size(); ++i)
        if (inside_region(faces[i], q))
            return int(i);
    return -1;
}

namespace {

// A drawing that cannot be read at all: no CUT loop, a bad kerf, a loop or line that is
// degenerate, crosses itself or lies beyond ±1e6 mm.
void check_readable(const SheetDrawing& d, Result<std::vector<DrawnPiece>>& r)
{
    const std::string file = d.name.empty() ? "the drawing" : d.name;
    if (d.cut.empty())
        r.fail(DiagnosticCode::drawing_unusable, file + ": no loop on the CUT layer");
    if (!std::isfinite(d.kerf) || d.kerf < 0.0 || d.kerf > 2.0)
        r.fail(DiagnosticCode::drawing_unusable,
               file + ": kerf = " + std::to_string(d.kerf) + ", must be 0 to 2 mm",
               about_parameter("kerf"));
    for (const Loop2& l : d.cut)
        if (l.size() < 3 || !finite_loop(l))
            r.fail(DiagnosticCode::drawing_unusable,
                   file + ": a CUT loop has " + std::to_string(l.size()) +
                       (finite_loop(l) ? " points, needs three or more"
                                       : " points and a coordinate that is not finite or "
                                         "lies beyond ±1e6 mm"));
        else if (const auto at = first_loop_crossing({l}))
            r.fail(DiagnosticCode::drawing_unusable, file + ": a CUT loop crosses itself at " +
                                                         where(*at) +
                                                         ": the paper it encloses is not defined");
    for (const Loop2& l : d.glue)
        if (l.size() < 3 || !finite_loop(l))
            r.fail(DiagnosticCode::drawing_unusable,
                   file + ": a GLUE area needs three or more points within ±1e6 mm");
    for (const DrawnFold& f : d.folds)
        if (!finite_loop({f.from, f.to}) || (f.to - f.from).norm() < 1e-6)
            r.fail(DiagnosticCode::drawing_unusable,
                   file + ": a fold line at " + where(f.from) +
                       " has no length, or a coordinate that is not finite or lies beyond "
                       "±1e6 mm");
    for (const DrawnText& t : d.labels)
        if (!finite_loop({t.position}))
            r.fail(DiagnosticCode::drawing_unusable,
                   file + ": label '" + t.text +
                       "' has a position that is not finite or lies beyond ±1e6 mm");
}

// The glue areas' codes among the texts on the piece; the texts no area takes stay the piece's.
void assign_glue_codes(DrawnPiece& piece, const std::vector<const DrawnText*>& texts)
{
    // A glue area's code is printed inside it; areas on the paper's two faces may
    // overlap, and a code inside several is the smallest one's (a larger area's code
    // is printed clear of the smaller areas on it). Each area takes the nearest of its
    // codes to its middle; then, of the texts no area took, the nearest inside it.
    std::vector<int> smallest(texts.size(), -1);
    for (size_t i = 0; i < texts.size(); ++i)
        for (size_t k = 0; k < piece.glue.size(); ++k)
            if (point_in_polygon(piece.glue[k].polygon, texts[i]->position) &&
                (smallest[i] < 0 ||
                 std::abs(loop_area(piece.glue[k].polygon)) <
                     std::abs(loop_area(piece.glue[size_t(smallest[i])].polygon))))
                smallest[i] = int(k);
    std::vector<bool> taken(texts.size(), false);
    std::vector<int> code_of(piece.glue.size(), -1);
    for (size_t k = 0; k < piece.glue.size(); ++k)
        for (size_t i = 0; i < texts.size(); ++i)
            if (smallest[i] == int(k) &&
                (code_of[k] < 0 ||
                 (texts[i]->position - mean(piece.glue[k].polygon)).norm() <
                     (texts[size_t(code_of[k])]->position - mean(piece.glue[k].polygon)).norm()))
                code_of[k] = int(i);
    for (int i : code_of)
        if (i >= 0)
            taken[size_t(i)] = true;
    for (size_t k = 0; k < piece.glue.size(); ++k) {
        DrawnGlue& g = piece.glue[k];
        int nearest = code_of[k];
        for (size_t i = 0; i < texts.size() && code_of[k] < 0; ++i)
            if (!taken[i] && point_in_polygon(g.polygon, texts[i]->position) &&
                (nearest < 0 || (texts[i]->position - mean(g.polygon)).norm() <
                                    (texts[size_t(nearest)]->position - mean(g.polygon)).norm()))
                nearest = int(i);
        if (nearest < 0)
            continue;
        taken[size_t(nearest)] = true;
        const std::string& text = texts[size_t(nearest)]->text;
        const std::string back = " (back)";
        g.back = text.size() > back.size() &&
                 text.compare(text.size() - back.size(), back.size(), back) == 0;
        g.code = g.back ? text.substr(0, text.size() - back.size()) : text;
    }
    for (size_t i = 0; i < texts.size(); ++i)
        if (!taken[i])
            piece.texts.push_back(*texts[i]);
}

// The pieces of one drawing: each cut region with its one piece label, the folds, glue areas
// and texts inside it (each entity to the innermost region around it), split into faces.
void read_pieces(const SheetDrawing& d, std::map<std::string, std::string>& seen,
                 Diagnostics& findings, std::vector<DrawnPiece>& pieces)
{
    const std::string file = d.name.empty() ? "the drawing" : d.name;
    std::vector<Region> regions = nominal_regions(d.cut, d.kerf);
    // Each entity belongs to the innermost piece around it: a small piece may be nested in
    // a large one's hole, and a slit's slot may sit on a fold.
    std::vector<double> areas;
    for (const Region& r : regions)
        areas.push_back(std::abs(loop_area(r.outer)));
    auto owner = [&](const Vec2& q) {
        int best = -1;
        for (size_t i = 0; i < regions.size(); ++i)
            if (point_in_polygon(regions[i].outer, q) && (best < 0 || areas[i] < areas[best]))
                best = int(i);
        return best;
    };
    for (size_t index = 0; index < regions.size(); ++index) {
        Region& region = regions[index];
        std::vector<std::string> ids;
        for (const DrawnText& t : d.labels)
            if (std::regex_match(t.text, piece_label) && owner(t.position) == int(index))
                ids.push_back(t.text);
        const Vec2 at = interior_point(region);
        const int self = int(index);
        const bool bare = std::none_of(d.folds.begin(), d.folds.end(),
                                       [&](const DrawnFold& f) {
                                           return owner(0.5 * (f.from + f.to)) == self;
                                       }) &&
                          std::none_of(d.labels.begin(), d.labels.end(), [&](const DrawnText& t) {
                              return owner(t.position) == self;
                          });
        if (ids.empty() && bare) { // a scrap that carries nothing a maker needs
            std::ostringstream m;
            m.precision(3);
            m << file << ": a scrap of " << areas[index] << " mm² around " << where(at)
              << " carries no label, fold or glue area: left out";
            findings.push_back(Diagnostic::warning(DiagnosticCode::unlabelled_piece, m.str()));
            continue;
        }
        if (ids.size() != 1) {
            findings.push_back(Diagnostic::error(
                DiagnosticCode::unlabelled_piece,
                file + ": the cut piece around " + where(at) + " carries " +
                    (ids.empty() ? std::string("no piece label (P1, P2, …)")
                                 : std::to_string(ids.size()) + " piece labels")));
            continue;
        }
        if (seen.count(ids[0])) {
            findings.push_back(Diagnostic::error(DiagnosticCode::unlabelled_piece,
                                                 file + ": piece label " + ids[0] +
                                                     " is on two cut pieces (" + seen[ids[0]] +
                                                     " and " + where(at) + ")"));
            continue;
        }
        seen[ids[0]] = file + " " + where(at);
        DrawnPiece piece;
        piece.id = ids[0];
        piece.drawing = file;
        piece.outline = region;
        for (const DrawnFold& f : d.folds)
            if (owner(0.5 * (f.from + f.to)) == self)
                piece.folds.push_back(f);
        for (const Loop2& g : d.glue)
            if (owner(interior_point({g, {}})) == self)
                piece.glue.push_back({g, "", false});
        std::vector<const DrawnText*> texts;
        for (const DrawnText& t : d.labels)
            if (t.text != piece.id && owner(t.position) == self)
                texts.push_back(&t);
        assign_glue_codes(piece, texts);
        piece.faces = split_faces(piece.outline, piece.folds);
        pieces.push_back(std::move(piece));
    }
}

} // namespace

Result<std::vector<DrawnPiece>> read_drawn_pieces(const std::vector<SheetDrawing>& drawings,
                                                  Diagnostics& findings)
{
    Result<std::vector<DrawnPiece>> r;
    if (drawings.empty())
        r.fail(DiagnosticCode::drawing_unusable, "no drawing to verify");
    for (const SheetDrawing& d : drawings)
        check_readable(d, r);
    if (!r.ok)
        return r;

    std::map<std::string, std::string> seen; // piece id → where
    for (const SheetDrawing& d : drawings)
        read_pieces(d, seen, findings, r.value);
    return r;
}

} // namespace popup::sheets
