#include "popup/model/apply_profile.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "../geometry/clipper_paths.hpp"
#include "../geometry/segment_in_region.hpp"
#include "../geometry/snap_onto_lines.hpp"

namespace popup {

namespace {

struct Region {
    Loop2 outer;
    std::vector<Loop2> holes;
};

// Outlines of a Clipper tree with their holes; islands inside holes are regions of their own.
void collect(const ClipperLib::PolyNode& node, std::vector<Region>& regions)
{
    for (const ClipperLib::PolyNode* outer : node.Childs) {
        Region region{to_loop(outer->Contour), {}};
        for (const ClipperLib::PolyNode* hole : outer->Childs) {
            region.holes.push_back(to_loop(hole->Contour));
            collect(*hole, regions);
        }
        regions.push_back(std::move(region));
    }
}

// Outer loops counter-clockwise, holes clockwise: filled "positive", a stray hole counts for
// nothing.
void add_region(ClipperLib::Clipper& clipper, const Loop2& outer, const std::vector<Loop2>& holes,
                ClipperLib::PolyType type)
{
    ClipperLib::Paths paths = counter_clockwise_paths({outer});
    for (ClipperLib::Path hole : counter_clockwise_paths(holes)) {
        ClipperLib::ReversePath(hole);
        paths.push_back(std::move(hole));
    }
    clipper.AddPaths(paths, type, true);
}

double region_area(const Region& r)
{
    double a = std::abs(path_area(to_path(r.outer)));
    for (const Loop2& h : r.holes)
        a -= std::abs(path_area(to_path(h)));
    return a;
}

std::string title(const Scaffold& s, int id)
{
    const Patch* p = s.find_patch(id);
    return !p || p->name.empty() ? "patch " + std::to_string(id) : p->name;
}

// Profile diagnostics name the patch and the parameter at fault.
DiagnosticSubject about_profile(int patch_id)
{
    return {{patch_id}, std::string("Profile"), std::nullopt};
}

// How far Clipper may put a vertex that belongs on a line off it: half a unit per coordinate
// when it rounds an input vertex, about twice that for a crossing it computes; with a margin.
constexpr double clipper_rounding = 4.0 / clipper_scale;

std::vector<const Loop2*> loops_of(const Loop2& outer, const std::vector<Loop2>& holes)
{
    std::vector<const Loop2*> loops{&outer};
    for (const Loop2& h : holes)
        loops.push_back(&h);
    return loops;
}

// A fold or a slit of the patch, as a segment to clip.
struct Edge {
    bool slit = false;
    size_t index = 0; ///< into scaffold.hinges or scaffold.slits
    Vec3 from, to;
};

using Intervals = std::vector<std::pair<double, double>>;

// The patch's outline and holes in the profile's frame.
void in_frame(const Patch& patch, const ProfileFrame& f, Loop2& outer, std::vector<Loop2>& holes)
{
    for (const Vec3& x : patch.outer)
        outer.push_back(f.to_frame(x));
    for (const Loop3& hole : patch.holes) {
        holes.emplace_back();
        for (const Vec3& x : hole)
            holes.back().push_back(f.to_frame(x));
    }
}

// (what the mechanism allows) ∩ profile, exact on the nanometre grid; slivers left out.
std::vector<Region> paper_left(const Loop2& outer, const std::vector<Loop2>& holes,
                               const Profile& profile, double tol)
{
    ClipperLib::Clipper clipper;
    clipper.StrictlySimple(true);
    add_region(clipper, outer, holes, ClipperLib::ptSubject);
    add_region(clipper, profile.outer, profile.holes, ClipperLib::ptClip);
    ClipperLib::PolyTree tree;
    clipper.Execute(ClipperLib::ctIntersection, tree, ClipperLib::pftPositive,
                    ClipperLib::pftPositive);
    std::vector<Region> pieces;
    collect(tree, pieces);
    pieces.erase(std::remove_if(pieces.begin(), pieces.end(),
                                [&](const Region& p) { return region_area(p) <= tol * tol; }),
                 pieces.end());
    return pieces;
}

// The patch's folds and slits.
std::vector<Edge> edges_of(const Scaffold& scaffold, int patch_id)
{
    std::vector<Edge> edges;
    for (size_t i = 0; i < scaffold.hinges.size(); ++i) {
        const Hinge& h = scaffold.hinges[i];
        if (h.patch_a == patch_id || h.patch_b == patch_id)
            edges.push_back({false, i, h.from, h.to});
    }
    for (size_t i = 0; i < scaffold.slits.size(); ++i)
        if (scaffold.slits[i].patch_cut == patch_id)
            edges.push_back({true, i, scaffold.slits[i].from, scaffold.slits[i].to});
    return edges;
}

// The exact corners, edges and folds of the patch, for the cut outline to snap back onto.
SnapTargets exact_targets(const Loop2& outer, const std::vector<Loop2>& holes,
                          const std::vector<Edge>& edges, const ProfileFrame& f)
{
    SnapTargets exact;
    for (const Loop2* loop : loops_of(outer, holes))
        for (size_t i = 0; i < loop->size(); ++i) {
            exact.corners.push_back((*loop)[i]);
            exact.lines.push_back({(*loop)[i], (*loop)[(i + 1) % loop->size()]});
        }
    for (const Edge& e : edges) {
        exact.corners.push_back(f.to_frame(e.from));
        exact.corners.push_back(f.to_frame(e.to));
        exact.lines.push_back({f.to_frame(e.from), f.to_frame(e.to)});
    }
    return exact;
}

// Each fold and slit cut to its stretches of paper: the first stretch keeps the joint's id, each
// other becomes a joint of its own.
void cut_joints(Scaffold& scaffold, const std::vector<Edge>& edges,
                const std::vector<Intervals>& kept_along, ProfileApplied& done)
{
    int next_hinge = 0, next_slit = 0;
    for (const Hinge& h : scaffold.hinges)
        next_hinge = std::max(next_hinge, h.id + 1);
    for (const Slit& s : scaffold.slits)
        next_slit = std::max(next_slit, s.id + 1);
    for (size_t k = 0; k < edges.size(); ++k) {
        const Edge& e = edges[k];
        const Vec3 d = e.to - e.from;
        for (size_t j = 0; j < kept_along[k].size(); ++j) {
            const Vec3 from = e.from + kept_along[k][j].first * d;
            const Vec3 to = e.from + kept_along[k][j].second * d;
            if (e.slit) {
                Slit s = scaffold.slits[e.index];
                s.from = from;
                s.to = to;
                if (j == 0)
                    scaffold.slits[e.index] = s;
                else {
                    s.id = next_slit++;
                    scaffold.slits.push_back(s);
                }
            } else {
                Hinge h = scaffold.hinges[e.index];
                h.from = from;
                h.to = to;
                if (j > 0)
                    h.id = next_hinge++;
                if (j == 0)
                    scaffold.hinges[e.index] = h;
                else
                    scaffold.hinges.push_back(h);
                done.hinges.push_back(h.id);
            }
        }
    }
}

} // namespace

Result<ProfileApplied> apply_profile(Scaffold& scaffold, int patch_id, const Profile& raw)
{
    Result<ProfileApplied> r;
    const Result<Profile> checked = checked_profile(raw);
    if (!checked.ok) {
        r.fail_with(checked.diagnostics);
        for (Diagnostic& d : r.diagnostics) {
            d.patches = {patch_id};
            d.parameter = "Profile";
        }
        return r;
    }
    const Profile& profile = checked.value;
    const Result<ProfileFrame> framed = profile_frame(scaffold, patch_id);
    if (!framed.ok) {
        r.fail_with(framed.diagnostics);
        return r;
    }
    const ProfileFrame& f = framed.value;
    const int index = scaffold.patch_index(patch_id);
    Patch& patch = scaffold.patches[index];
    const std::string patch_name = title(scaffold, patch_id);
    const std::string what = patch_name + ": profile '" + profile.name + "'";

    Loop2 outer;
    std::vector<Loop2> holes;
    in_frame(patch, f, outer, holes);
    const double tol = std::max(1e-6 * scaffold.size(), 2.0 / clipper_scale);
    const std::vector<Region> pieces = paper_left(outer, holes, profile, tol);
    if (pieces.empty()) {
        r.fail(DiagnosticCode::bad_profile,
               what + " leaves no paper: the outline and the patch do not overlap (outlines are "
                      "in the patch's profile frame, docs/DESIGN.md)",
               about_profile(patch_id));
        return r;
    }

    const std::vector<Edge> edges = edges_of(scaffold, patch_id);
    const double shortest = shortest_fold(scaffold);
    auto clip = [&](const Region& piece, const Edge& e) {
        return segment_in_region(f.to_frame(e.from), f.to_frame(e.to), piece.outer, piece.holes,
                                 tol, shortest);
    };
    // Keep the piece that holds the folds; loose paper falls away.
    std::vector<size_t> holding;
    for (size_t k = 0; k < pieces.size(); ++k)
        if (edges.empty() || std::any_of(edges.begin(), edges.end(), [&](const Edge& e) {
                return !clip(pieces[k], e).empty();
            }))
            holding.push_back(k);
    if (holding.size() > 1) {
        r.fail(DiagnosticCode::bad_profile,
               what + " cuts it into " + std::to_string(holding.size()) +
                   " pieces that each hold a fold; a patch is one piece of paper: join them in "
                   "the outline or leave one out",
               about_profile(patch_id));
        return r;
    }
    const size_t kept = holding.empty() ? 0 : holding.front();
    Region piece = pieces[kept];
    // Back onto the exact corners, edges and folds of the patch: off them by a grid unit, the
    // folds the sheets draw through the outline's corners leave the card remade from them out of
    // line, and a linkage with parallel folds (a box) then jams (docs/DESIGN.md).
    const SnapTargets exact = exact_targets(outer, holes, edges, f);
    snap_onto_lines(piece.outer, exact, clipper_rounding);
    for (Loop2& hole : piece.holes)
        snap_onto_lines(hole, exact, clipper_rounding);
    std::vector<Intervals> kept_along;
    for (const Edge& e : edges) {
        kept_along.push_back(clip(piece, e));
        if (!kept_along.back().empty())
            continue;
        std::ostringstream m;
        if (e.slit) {
            const Slit& s = scaffold.slits[e.index];
            m << what << " leaves no paper along slit " << s.id << " (where "
              << title(scaffold, s.patch_through) << " passes through)";
        } else {
            const Hinge& h = scaffold.hinges[e.index];
            const int other = h.patch_a == patch_id ? h.patch_b : h.patch_a;
            m << what << " leaves no paper along fold " << h.id << " (" << patch_name << "–"
              << title(scaffold, other) << "): the outline must run along at least " << shortest
              << " mm of it, or the patch comes loose";
        }
        r.fail(DiagnosticCode::profile_misses_hinge, m.str(), about_profile(patch_id));
        return r;
    }

    // Commit: the patch, then each fold and slit cut to its stretches of paper.
    ProfileApplied& done = r.value;
    done.patch = patch_id;
    done.frame = f;
    done.area_before = patch.area();
    done.dropped_pieces = int(pieces.size()) - 1;
    auto to_world = [&](const Loop2& loop, bool counter_clockwise) {
        ClipperLib::Path path = to_path(loop);
        Loop3 out;
        for (const Vec2& q : loop)
            out.push_back(f.to_world(q));
        if (ClipperLib::Orientation(path) != counter_clockwise)
            std::reverse(out.begin(), out.end());
        return out;
    };
    patch.outer = to_world(piece.outer, true);
    patch.holes.clear();
    for (const Loop2& hole : piece.holes)
        patch.holes.push_back(to_world(hole, false));
    patch.derive_frame();
    done.area_after = patch.area();
    cut_joints(scaffold, edges, kept_along, done);
    if (done.dropped_pieces > 0)
        r.warn(DiagnosticCode::bad_profile,
               what + " cut off " + std::to_string(done.dropped_pieces) +
                   " piece(s) of paper holding no fold; they were dropped",
               about_profile(patch_id));
    done.warnings = r.diagnostics;
    return r;
}

Result<ProfileApplied> apply_profile(Scaffold& scaffold, const std::string& mechanism,
                                     const std::string& part, const Profile& profile)
{
    const std::string name = mechanism + "." + part;
    std::string parts;
    for (const Patch& p : scaffold.patches) {
        if (p.name == name)
            return apply_profile(scaffold, p.id, profile);
        if (p.name.rfind(mechanism + ".", 0) == 0)
            parts += (parts.empty() ? "" : ", ") + p.name.substr(mechanism.size() + 1);
    }
    Result<ProfileApplied> r;
    r.fail(DiagnosticCode::unknown_patch,
           "profile '" + profile.name + "': " + mechanism + " has no part " + part +
               (parts.empty() ? " (the design has no mechanism " + mechanism + ")"
                              : " (its parts: " + parts + ")"),
           about_parameter("ProfilePart"));
    return r;
}

} // namespace popup
