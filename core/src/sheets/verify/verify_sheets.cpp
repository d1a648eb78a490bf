#include "popup/sheets/verify_sheets.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <set>
#include <sstream>

#include "../../geometry/clipper_paths.hpp"
#include "../../geometry/polygon_2d.hpp"
#include "../../model/millimetres.hpp"
#include "../assembly_order.hpp"
#include "../clipper_ops.hpp"
#include "../fold_directions.hpp"
#include "../local_piece.hpp"
#include "drawn_piece.hpp"
#include "popup/sheets/pieces.hpp"
#include "popup/simulation/simulate_fold.hpp"
#include "register_piece.hpp"

namespace popup {

using namespace sheets;

namespace {

constexpr double fold_snap = 1e-5; // mm: a drawn fold this near its designed line is on it
constexpr double side_step = 1e-4; // mm beside a fold line: a point in the face on either side

std::string at(const Vec2& p)
{
    std::ostringstream s;
    s.precision(6);
    s << "(" << p.x() << ", " << p.y() << ")";
    return s.str();
}

const char* layer(FoldDirection d)
{
    return d == FoldDirection::mountain ? "MOUNTAIN" : "VALLEY";
}

Vec3 lift(const Vec2& p)
{
    return {p.x(), p.y(), 0.0};
}

Pose turn_about(const Vec3& point, const Vec3& axis, double angle)
{
    Pose p;
    p.rotation = axis_angle(axis, angle);
    p.translation = point - p.rotation * point;
    return p;
}

// Signed angle of a rotation about `axis` (unit), read from how it turns a perpendicular.
double angle_about(const Mat3& rotation, const Vec3& axis)
{
    Vec3 u = axis.cross(std::abs(axis.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).normalized();
    const Vec3 turned = rotation * u;
    return std::atan2(axis.dot(u.cross(turned)), u.dot(turned));
}

double pose_gap(const Pose& a, const Pose& b, double scale)
{
    return (a.rotation - b.rotation).norm() * scale + (a.translation - b.translation).norm();
}

// Largest distance from a point of one loop to the other loop (both ways), in 3D.
double loop_gap(const Loop3& a, const Loop3& b)
{
    auto one_way = [](const Loop3& from, const Loop3& onto) {
        double worst = 0.0;
        for (const Vec3& q : from) {
            double near = 1e300;
            for (size_t i = 0; i < onto.size(); ++i) {
                const Vec3 &p0 = onto[i], &p1 = onto[(i + 1) % onto.size()];
                const Vec3 d = p1 - p0;
                const double t =
                    std::clamp((q - p0).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
                near = std::min(near, (p0 + t * d - q).norm());
            }
            worst = std::max(worst, near);
        }
        return worst;
    };
    return std::max(one_way(a, b), one_way(b, a));
}

std::string patch_name(const Scaffold& s, int id)
{
    const Patch* p = s.find_patch(id);
    return "'" + (p ? p->name : std::string("?")) + "' (" + std::to_string(id) + ")";
}

// One piece of the design and what the drawing makes of it.
struct PieceCheck {
    std::string id;
    LocalPiece local;
    const DrawnPiece* drawn = nullptr;
    std::vector<Registration> candidates; // the ways it fits the drawing equally well
    Registration placed;                  // the one chosen
    std::map<int, int> face_of;           // patch id → drawn face
    std::map<int, Pose> sheet_pose;       // patch id → design state onto the drawing (z = 0)
    std::map<int, int> fold_of;           // fold hinge id → drawn fold
    std::map<int, bool> fold_turned;      // fold hinge id → drawn the other way than designed
    std::set<int> folds_used;             // drawn folds that are a fold or a tab crease

    int patch_of_face(int face) const
    {
        for (const auto& [patch, f] : face_of)
            if (f == face)
                return patch;
        return -1;
    }
};

struct DrawnTab {
    size_t piece = 0; // PieceCheck index
    int patch = 0;    // the patch it hangs from
    int hinge = -1;   // the design's tab joint it makes
    int crease = 0;   // drawn fold index on its piece
    std::string code;
};

struct DrawnArea {
    size_t piece = 0;
    int patch = -1;
    const DrawnGlue* glue = nullptr;
};

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

// A drawn line with a patch's face on one side and a face that is no patch on the other is the
// crease of a tab: that patch and the tab's face, or -1s. `patch_of` maps a face (or -1) to its
// patch (or -1).
template <class PatchOf>
std::pair<int, int> tab_crease(const DrawnPiece& piece, const DrawnFold& f, PatchOf patch_of)
{
    const auto [left, right] = sides(piece, f);
    const int pl = patch_of(left), pr = patch_of(right);
    if (pl >= 0 && pr < 0)
        return {pl, right};
    if (pr >= 0 && pl < 0)
        return {pr, left};
    return {-1, -1};
}

std::vector<Region> union_of(const LocalPiece& local)
{
    ClipperLib::Clipper clipper;
    clipper.AddPaths(counter_clockwise_paths(local.flat.outlines), ClipperLib::ptSubject, true);
    std::vector<Loop2> holes;
    for (const auto& h : local.flat.holes)
        holes.insert(holes.end(), h.begin(), h.end());
    clipper.AddPaths(counter_clockwise_paths(holes), ClipperLib::ptClip, true);
    ClipperLib::PolyTree tree;
    clipper.Execute(ClipperLib::ctDifference, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    std::vector<Region> regions;
    collect_regions(tree, regions);
    return regions;
}

class Verifier {
public:
    Verifier(const Scaffold& s, const VerifyOptions& options, Diagnostics& findings)
        : s_(s), options_(options), findings_(findings), tol_(1e-6 * s.size())
    {
    }

    bool prepare(Result<RoundTrip>& r);
    void match(const std::vector<DrawnPiece>& drawn);
    void check_folds(PieceCheck& piece);
    void check_tabs();
    bool place(std::map<int, Pose>& from_sheet);
    RoundTrip compare(const std::map<int, Pose>& from_sheet);

    bool structural = false; // the drawing cannot be rebuilt into the design's card

private:
    void error(DiagnosticCode code, const std::string& message, std::vector<int> patches = {})
    {
        findings_.push_back(Diagnostic::error(code, message, about_patches(std::move(patches))));
    }
    const Hinge& hinge(int id) const
    {
        return *std::find_if(s_.hinges.begin(), s_.hinges.end(),
                             [&](const Hinge& h) { return h.id == id; });
    }
    int piece_of(int patch) const
    {
        for (size_t k = 0; k < pieces_.size(); ++k)
            if (pieces_[k].local.has(patch))
                return int(k);
        return -1;
    }
    // Hinge h's line runs through the inside of `patch` (its paper lies on both sides of it).
    bool joint_inside(int patch, const Hinge& h) const
    {
        const int k = piece_of(patch);
        if (k < 0)
            return false;
        const LocalPiece& local = pieces_[size_t(k)].local;
        const Vec2 a = local.flat_point(s_, patch, h.from), b = local.flat_point(s_, patch, h.to);
        const Vec2 across = left_normal((b - a).normalized());
        double lowest = 0.0, highest = 0.0;
        for (const Vec2& p : local.outline(patch)) {
            lowest = std::min(lowest, across.dot(p - a));
            highest = std::max(highest, across.dot(p - a));
        }
        return lowest < -tol_ && highest > tol_;
    }
    void join(std::map<int, Pose>& from_sheet, int moving, const PieceCheck& moving_piece,
              std::array<Vec2, 2> moving_edge, int fixed, const PieceCheck& fixed_piece,
              std::array<Vec2, 2> fixed_edge);
    void fold_from(std::map<int, Pose>& from_sheet, const PieceCheck& piece, int start);
    void choose_registrations();
    std::map<int, int> faces_of(const PieceCheck& piece, const Registration& placed) const;

    const Scaffold& s_;
    const VerifyOptions& options_;
    Diagnostics& findings_;
    double tol_;
    double tie_ = 1e-3;          // mm: registrations this close in fit are the same fit
    std::vector<double> angles_; // the angles asked for and the fold-direction samples
    std::vector<double> asked_;
    Result<FoldSweep> designed_;
    BendSamples bends_;
    std::vector<PieceCheck> pieces_;
    std::vector<DrawnTab> tabs_;
    std::map<std::string, DrawnArea> areas_; // by code: the glue area a tab goes onto
};

bool Verifier::prepare(Result<RoundTrip>& r)
{
    const auto groups = cut_pieces(s_);
    Diagnostics order_notes;
    const std::vector<int> order = assembly_order(s_, groups, order_notes);
    for (const auto& [id, side] : options_.printed_sides) {
        const bool known = id.size() > 1 && id[0] == 'P' &&
                           id.find_first_not_of("0123456789", 1) == std::string::npos &&
                           std::stoul(id.substr(1)) >= 1 &&
                           std::stoul(id.substr(1)) <= order.size();
        if (!known)
            r.fail(DiagnosticCode::bad_option,
                   "printed side of " + id + ": there is no such piece; the pieces are P1 to P" +
                       std::to_string(order.size()),
                   about_parameter("printed_sides"));
    }
    if (!r.ok)
        return false;
    for (int g : order) {
        PieceCheck piece;
        piece.id = "P" + std::to_string(pieces_.size() + 1);
        const auto side = options_.printed_sides.find(piece.id);
        const bool back = side != options_.printed_sides.end() && side->second == PrintedSide::back;
        Result<LocalPiece> flat = lay_flat(s_, groups[g], 1e-6 * std::max(s_.size(), 1.0), back);
        if (!flat.ok) {
            r.fail_with(flat.diagnostics);
            return false;
        }
        piece.local = std::move(flat.value);
        pieces_.push_back(std::move(piece));
    }
    angles_ = sweep_angles(s_, options_.angles);
    for (int k = 0; k < options_.angles; ++k)
        asked_.push_back(s_.design_angle * (1.0 - double(k) / (options_.angles - 1)));
    SimulationOptions simulation;
    simulation.cancel = options_.cancel;
    designed_ = simulate_fold(s_, angles_, simulation);
    if (!designed_.ok) {
        r.fail(DiagnosticCode::round_trip_failed,
               "the design does not simulate: " + (designed_.diagnostics.empty()
                                                       ? std::string("no reason given")
                                                       : designed_.diagnostics.front().message));
        return false;
    }
    bends_ = sample_bends(s_, designed_.value.states);
    return true;
}

void Verifier::match(const std::vector<DrawnPiece>& drawn)
{
    for (const DrawnPiece& d : drawn)
        if (std::none_of(pieces_.begin(), pieces_.end(),
                         [&](const PieceCheck& p) { return p.id == d.id; })) {
            error(DiagnosticCode::unlabelled_piece,
                  d.drawing + ": " + d.id + " is not a piece of the design (it has P1 to P" +
                      std::to_string(pieces_.size()) + ")");
            structural = true;
        }
    for (PieceCheck& piece : pieces_) {
        const LocalPiece& local = piece.local;
        for (const DrawnPiece& d : drawn)
            if (d.id == piece.id)
                piece.drawn = &d;
        if (!piece.drawn) {
            error(DiagnosticCode::missing_piece, piece.id + " is on no sheet", local.flat.patches);
            structural = true;
            continue;
        }
        std::vector<std::array<Vec2, 2>> joints;
        for (const Hinge& h : s_.hinges)
            for (int patch : {h.patch_a, h.patch_b})
                if (h.kind == JointKind::tab && local.has(patch))
                    joints.push_back(
                        {local.flat_point(s_, patch, h.from), local.flat_point(s_, patch, h.to)});
        piece.candidates = register_piece(local.flat.outlines, union_of(local),
                                          local.flat.fold_lines, joints, *piece.drawn, tol_ + tie_);
        if (piece.candidates.empty()) {
            error(DiagnosticCode::outline_mismatch,
                  piece.id + ": none of its faces has the shape of a patch of the design",
                  local.flat.patches);
            structural = true;
            piece.drawn = nullptr;
        }
    }
    choose_registrations();
    for (PieceCheck& piece : pieces_) {
        if (!piece.drawn)
            continue;
        const LocalPiece& local = piece.local;
        const DrawnPiece& d = *piece.drawn;
        if (piece.placed.outline_error > tol_)
            error(DiagnosticCode::outline_mismatch,
                  piece.id + ": its cut outline is " + millimetres(piece.placed.outline_error) +
                      " off the design's (farthest at " + at(piece.placed.outline_worst) + " on " +
                      d.drawing + ")",
                  local.flat.patches);
        // Design state → the root's plane → its 2D frame (turned over for a back print) → drawing.
        const Patch& root = *s_.find_patch(local.flat.patches.front());
        Pose frame;
        const double turned = local.printed_back ? -1.0 : 1.0;
        frame.rotation.row(0) = root.u.transpose();
        frame.rotation.row(1) = turned * root.v.transpose();
        frame.rotation.row(2) = turned * root.normal.transpose();
        frame.translation = -(frame.rotation * root.origin);
        Pose onto;
        onto.rotation.topLeftCorner<2, 2>() = piece.placed.motion.rotation;
        onto.translation = lift(piece.placed.motion.translation);
        for (size_t i = 0; i < local.flat.patches.size(); ++i) {
            const int id = local.flat.patches[i];
            piece.sheet_pose[id] = local.flat.unfold[i].then(frame).then(onto);
            const Vec2 inside =
                piece.placed.motion(interior_point({local.flat.outlines[i], local.flat.holes[i]}));
            const int face = d.face_at(inside);
            if (face < 0) {
                error(DiagnosticCode::outline_mismatch,
                      piece.id + ": patch " + patch_name(s_, id) + " is not on the cut piece (" +
                          at(inside) + " on " + d.drawing + " is off the paper)",
                      {id});
                structural = true;
                continue;
            }
            if (const int other = piece.patch_of_face(face); other >= 0) {
                error(DiagnosticCode::fold_not_separating,
                      piece.id + ": patches " + patch_name(s_, other) + " and " +
                          patch_name(s_, id) + " lie in one face: no fold line cuts between them",
                      {other, id});
                structural = true;
                continue;
            }
            piece.face_of[id] = face;
        }
        check_folds(piece);
    }
}

void Verifier::check_folds(PieceCheck& piece)
{
    const LocalPiece& local = piece.local;
    const DrawnPiece& d = *piece.drawn;
    const Motion2& m = piece.placed.motion;
    for (size_t i = 0; i < local.flat.folds.size(); ++i) {
        const Hinge& h = hinge(local.flat.folds[i]);
        const std::array<Vec2, 2> line{m(local.flat.fold_lines[i][0]),
                                       m(local.flat.fold_lines[i][1])};
        const std::string what = piece.id + ": the fold between patches " +
                                 patch_name(s_, h.patch_a) + " and " + patch_name(s_, h.patch_b) +
                                 " (hinge " + std::to_string(h.id) + ")";
        // The drawn line between the two patches' faces, else the nearest one.
        int best = -1;
        double gap = 1e300;
        const auto fa = piece.face_of.find(h.patch_a), fb = piece.face_of.find(h.patch_b);
        for (size_t k = 0; k < d.folds.size(); ++k) {
            const DrawnFold& f = d.folds[k];
            const double g = std::max(segment_gap(line, f.from, f.to),
                                      segment_gap({f.from, f.to}, line[0], line[1]));
            bool between = false;
            if (fa != piece.face_of.end() && fb != piece.face_of.end()) {
                const auto [left, right] = sides(d, f);
                between = (left == fa->second && right == fb->second) ||
                          (left == fb->second && right == fa->second);
            }
            const double rank = between ? g : g + 1e200;
            if (rank < gap) {
                gap = rank;
                best = int(k);
            }
        }
        if (best < 0 || gap >= 1e200) {
            error(DiagnosticCode::fold_missing, what + " has no fold line", {h.patch_a, h.patch_b});
            structural = true;
            continue;
        }
        piece.fold_of[h.id] = best;
        piece.folds_used.insert(best);
        if (gap > tol_)
            error(DiagnosticCode::fold_misplaced,
                  what + " is drawn " + millimetres(gap) + " off the design's crease",
                  {h.patch_a, h.patch_b});
        bool unspecified = false;
        const FoldDirection expected =
            drawn_direction(s_, bends_, h, local.printed_normal(s_, h.patch_a), unspecified);
        const FoldDirection drawn = d.folds[size_t(best)].direction;
        piece.fold_turned[h.id] = drawn != expected;
        if (drawn != expected)
            error(DiagnosticCode::fold_direction_wrong,
                  what + " is on the " + layer(drawn) + " layer; the design folds it " +
                      (expected == FoldDirection::mountain ? "a mountain" : "a valley") +
                      " seen from the printed side",
                  {h.patch_a, h.patch_b});
    }
}

void Verifier::check_tabs()
{
    std::map<std::string, std::vector<DrawnArea>> by_code;
    for (size_t k = 0; k < pieces_.size(); ++k) {
        const PieceCheck& piece = pieces_[k];
        if (!piece.drawn)
            continue;
        for (const DrawnGlue& g : piece.drawn->glue) {
            const int face = piece.drawn->face_at(interior_point({g.polygon, {}}));
            DrawnArea area{k, face >= 0 ? piece.patch_of_face(face) : -1, &g};
            if (g.code.empty()) {
                error(DiagnosticCode::tab_unmatched, piece.id + ": the glue area at " +
                                                         at(g.polygon.front()) +
                                                         " carries no code");
                continue;
            }
            if (area.patch < 0) {
                error(DiagnosticCode::tab_unmatched,
                      piece.id + ": glue area " + g.code + " lies on no patch of the piece");
                continue;
            }
            by_code[g.code].push_back(area);
        }
    }
    for (const auto& [code, areas] : by_code)
        if (areas.size() > 1)
            error(DiagnosticCode::tab_unmatched,
                  "glue code " + code + " is on " + std::to_string(areas.size()) + " glue areas");

    std::set<std::string> carried;
    for (size_t k = 0; k < pieces_.size(); ++k) {
        PieceCheck& piece = pieces_[k];
        if (!piece.drawn)
            continue;
        const DrawnPiece& d = *piece.drawn;
        for (size_t f = 0; f < d.folds.size(); ++f) {
            if (piece.folds_used.count(int(f)))
                continue;
            const auto [patch, tab_face] = tab_crease(d, d.folds[f], [&](int face) {
                return face >= 0 ? piece.patch_of_face(face) : -1;
            });
            if (tab_face < 0) {
                const DrawnFold& line = d.folds[f];
                error(DiagnosticCode::fold_extra,
                      piece.id + ": the " + layer(line.direction) + " line from " + at(line.from) +
                          " to " + at(line.to) + " is no fold or tab crease of the design",
                      piece.local.flat.patches);
                continue;
            }
            // Its code: a text on the tab that some glue area carries.
            std::string code;
            for (const DrawnText& t : d.texts)
                if (inside_region(d.faces[size_t(tab_face)], t.position) &&
                    (code.empty() || by_code.count(t.text)))
                    code = t.text;
            const auto areas = by_code.find(code);
            const int glued_to = areas == by_code.end() ? -1 : areas->second.front().patch;
            // The design's tab joint on this patch along the crease. Joints can share a line
            // (a patch between two others): the one the code glues to, else one not yet taken.
            const Motion2& m = piece.placed.motion;
            std::vector<std::pair<double, int>> joints;
            for (const Hinge& h : s_.hinges) {
                if (h.kind != JointKind::tab || (h.patch_a != patch && h.patch_b != patch))
                    continue;
                const std::array<Vec2, 2> line{m(piece.local.flat_point(s_, patch, h.from)),
                                               m(piece.local.flat_point(s_, patch, h.to))};
                joints.push_back(
                    {segment_gap({d.folds[f].from, d.folds[f].to}, line[0], line[1]), h.id});
            }
            std::sort(joints.begin(), joints.end());
            int joint = -1, free = -1, glued = -1;
            const double gap = joints.empty() ? 0.0 : joints.front().first;
            for (const auto& [g, id] : joints) {
                if (g > gap + tol_)
                    break;
                const Hinge& h = hinge(id);
                const int partner = h.patch_a == patch ? h.patch_b : h.patch_a;
                const bool taken = std::any_of(tabs_.begin(), tabs_.end(),
                                               [&](const DrawnTab& t) { return t.hinge == id; });
                joint = joint < 0 ? id : joint;
                free = free < 0 && !taken ? id : free;
                glued = glued < 0 && partner == glued_to ? id : glued;
            }
            joint = glued >= 0 ? glued : free >= 0 ? free : joint;
            if (joint < 0) {
                error(DiagnosticCode::fold_extra,
                      piece.id + ": a tab hangs from patch " + patch_name(s_, patch) +
                          ", which the design joins to no other piece",
                      {patch});
                continue;
            }
            piece.folds_used.insert(int(f));
            const Hinge& h = hinge(joint);
            const int partner = h.patch_a == patch ? h.patch_b : h.patch_a;
            if (gap > tol_)
                error(DiagnosticCode::fold_misplaced,
                      piece.id + ": the tab crease on patch " + patch_name(s_, patch) + " (hinge " +
                          std::to_string(h.id) + ") is drawn " + millimetres(gap) +
                          " off the design's joint",
                      {patch, partner});
            Hinge seen_from_tab = h;
            seen_from_tab.patch_a = patch;
            seen_from_tab.patch_b = partner;
            bool unspecified = false;
            FoldDirection expected = drawn_direction(
                s_, bends_, seen_from_tab, piece.local.printed_normal(s_, patch), unspecified);
            if (areas != by_code.end() && areas->second.front().patch == partner) {
                // The tab folds onto the side of the joint its glue area is drawn on (a joint
                // inside the partner's paper has room on both sides).
                const DrawnArea& area = areas->second.front();
                const PieceCheck& under = pieces_[area.piece];
                const Motion2& drawing = under.placed.motion;
                const Vec2 glue_point =
                    drawing.rotation.transpose() *
                    (interior_point({area.glue->polygon, {}}) - drawing.translation);
                bool bent = false;
                expected = tab_direction(s_, bends_, h, piece.local, patch, under.local, partner,
                                         glue_point, bent);
            }
            if (d.folds[f].direction != expected)
                error(DiagnosticCode::fold_direction_wrong,
                      piece.id + ": the tab crease on patch " + patch_name(s_, patch) + " (hinge " +
                          std::to_string(h.id) + ") is on the " + layer(d.folds[f].direction) +
                          " layer; the tab folds " +
                          (expected == FoldDirection::mountain ? "a mountain" : "a valley") +
                          " seen from the printed side",
                      {patch, partner});
            DrawnTab tab{k, patch, joint, int(f), code};
            const std::string name = piece.id + ": tab " + (code.empty() ? "(no code)" : code) +
                                     " on patch " + patch_name(s_, patch);
            if (areas == by_code.end()) {
                error(DiagnosticCode::tab_unmatched,
                      name + (code.empty() ? " carries no code"
                                           : " has no glue area carrying its code"),
                      {patch, partner});
                structural = true;
                continue;
            }
            carried.insert(code);
            const DrawnArea& area = areas->second.front();
            areas_[code] = area;
            if (area.patch != partner)
                error(DiagnosticCode::tab_wrong_target,
                      name + " is glued by its code onto patch " + patch_name(s_, area.patch) +
                          " of " + pieces_[area.piece].id + "; the design joins it to patch " +
                          patch_name(s_, partner) + " of " +
                          (piece_of(partner) >= 0 ? pieces_[size_t(piece_of(partner))].id : "?") +
                          // A piece that fits its drawing turned round as well cannot tell
                          // which of its tabs carries the wrong code.
                          (piece.candidates.size() > 1
                               ? " (" + piece.id +
                                     " fits its outline turned round too: the wrong code may be "
                                     "on another of its tabs)"
                               : std::string()),
                      {patch, partner, area.patch});
            tabs_.push_back(tab);
        }
    }
    for (const auto& [code, areas] : by_code)
        if (!carried.count(code)) {
            const DrawnArea& a = areas.front();
            error(DiagnosticCode::tab_unmatched,
                  pieces_[a.piece].id + ": glue area " + code + " on patch " +
                      patch_name(s_, a.patch) + " has no tab carrying its code",
                  {a.patch});
        }
    // Every joint between pieces needs its tab.
    for (const Hinge& h : s_.hinges) {
        if (h.kind != JointKind::tab)
            continue;
        const int pa = piece_of(h.patch_a), pb = piece_of(h.patch_b);
        if (pa == pb || pa < 0 || pb < 0 || !pieces_[size_t(pa)].drawn ||
            !pieces_[size_t(pb)].drawn)
            continue;
        // One tab holds every joint along its crease on its patch (a panel standing on the
        // central fold is joined to both pages along one edge); so does one glue area. The
        // crease may lie within the joint (a tab held back from its ends) or the joint within
        // the crease (an outline cut the other patch's edge short; glue_tabs' already_tabbed).
        auto along = [&](int patch, const Vec2& from, const Vec2& to) {
            if (patch != h.patch_a && patch != h.patch_b)
                return false;
            const PieceCheck& on = pieces_[size_t(piece_of(patch))];
            const std::array<Vec2, 2> line{on.placed.motion(on.local.flat_point(s_, patch, h.from)),
                                           on.placed.motion(on.local.flat_point(s_, patch, h.to))};
            return segment_gap({from, to}, line[0], line[1]) <= tol_ + tie_ ||
                   segment_gap(line, from, to) <= tol_ + tie_;
        };
        const bool held =
            std::any_of(tabs_.begin(), tabs_.end(),
                        [&](const DrawnTab& t) {
                            const DrawnFold& c = pieces_[t.piece].drawn->folds[size_t(t.crease)];
                            return t.hinge == h.id || along(t.patch, c.from, c.to);
                        }) ||
            std::any_of(areas_.begin(), areas_.end(), [&](const auto& a) {
                return along(a.second.patch, a.second.glue->polygon[0], a.second.glue->polygon[1]);
            });
        if (!held) {
            error(DiagnosticCode::joint_without_tab,
                  "the joint of patch " + patch_name(s_, h.patch_a) + " on " +
                      pieces_[size_t(pa)].id + " and patch " + patch_name(s_, h.patch_b) + " on " +
                      pieces_[size_t(pb)].id + " (hinge " + std::to_string(h.id) +
                      ") has no glue tab on the sheets",
                  {h.patch_a, h.patch_b});
            structural = true;
        }
    }
}

// Patch id → the drawn face holding its inside point, for one way of laying the piece down.
std::map<int, int> Verifier::faces_of(const PieceCheck& piece, const Registration& placed) const
{
    std::map<int, int> faces;
    const FlatPiece& flat = piece.local.flat;
    for (size_t i = 0; i < flat.patches.size(); ++i)
        faces[flat.patches[i]] =
            piece.drawn->face_at(placed.motion(interior_point({flat.outlines[i], flat.holes[i]})));
    return faces;
}

// A symmetric piece fits its drawing more than one way; the glue codes tell which is meant. Of
// all combinations (a few pieces with two or four ways each), the one whose tabs go onto the
// patches the design joins them to the most often wins; ties keep each piece's best fit.
void Verifier::choose_registrations()
{
    struct Way {
        struct Tab {
            std::map<int, FoldDirection> partners; // patches it may join → the crease they need
            FoldDirection drawn;
            std::string code;
        };
        std::vector<Tab> tabs;
        int folds_turned = 0;             // design folds whose drawn line has the other direction
        std::map<std::string, int> areas; // code → patch it lies on
    };
    std::vector<std::vector<Way>> ways(pieces_.size());
    size_t combinations = 1;
    for (size_t k = 0; k < pieces_.size(); ++k) {
        const PieceCheck& piece = pieces_[k];
        if (!piece.drawn)
            continue;
        const DrawnPiece& d = *piece.drawn;
        for (const Registration& r : piece.candidates) {
            const std::map<int, int> faces = faces_of(piece, r);
            auto patch_of = [&](int face) {
                for (const auto& [patch, f] : faces)
                    if (f == face && face >= 0)
                        return patch;
                return -1;
            };
            Way way;
            for (const DrawnGlue& g : d.glue)
                way.areas[g.code] = patch_of(d.face_at(interior_point({g.polygon, {}})));
            for (const DrawnFold& f : d.folds) {
                const auto [patch, tab_face] = tab_crease(d, f, patch_of);
                if (tab_face < 0)
                    continue;
                // The patches the joints along this crease join its patch to.
                std::map<int, FoldDirection> partners;
                for (const Hinge& h : s_.hinges)
                    if (h.kind == JointKind::tab && (h.patch_a == patch || h.patch_b == patch) &&
                        segment_gap(
                            {f.from, f.to}, r.motion(piece.local.flat_point(s_, patch, h.from)),
                            r.motion(piece.local.flat_point(s_, patch, h.to))) <= tol_ + tie_) {
                        Hinge seen = h;
                        seen.patch_a = patch;
                        seen.patch_b = h.patch_a == patch ? h.patch_b : h.patch_a;
                        bool unspecified = false;
                        // A joint inside the partner's paper lets the tab lie on either side
                        // of it, and fold either way: its crease tells nothing here.
                        partners[seen.patch_b] =
                            joint_inside(seen.patch_b, h)
                                ? FoldDirection::unspecified
                                : drawn_direction(s_, bends_, seen,
                                                  piece.local.printed_normal(s_, patch),
                                                  unspecified);
                    }
                for (const DrawnText& t : d.texts)
                    if (inside_region(d.faces[size_t(tab_face)], t.position))
                        way.tabs.push_back({partners, f.direction, t.text});
            }
            // Folds: the drawn line nearest each design fold, and its direction.
            const FlatPiece& flat = piece.local.flat;
            for (size_t i = 0; i < flat.folds.size(); ++i) {
                const Hinge& h = hinge(flat.folds[i]);
                const std::array<Vec2, 2> line{r.motion(flat.fold_lines[i][0]),
                                               r.motion(flat.fold_lines[i][1])};
                const DrawnFold* nearest = nullptr;
                double gap = 1e300;
                for (const DrawnFold& f : d.folds)
                    if (const double g = segment_gap(line, f.from, f.to); g < gap) {
                        gap = g;
                        nearest = &f;
                    }
                bool unspecified = false;
                if (nearest &&
                    nearest->direction != drawn_direction(s_, bends_, h,
                                                          piece.local.printed_normal(s_, h.patch_a),
                                                          unspecified))
                    ++way.folds_turned;
            }
            ways[k].push_back(std::move(way));
        }
        combinations =
            std::min<size_t>(combinations * std::max<size_t>(ways[k].size(), 1), size_t(1) << 20);
    }
    auto misfits = [&](const std::vector<size_t>& choice) {
        int count = 0;
        for (size_t k = 0; k < ways.size(); ++k) {
            if (ways[k].empty())
                continue;
            const Way& way = ways[k][choice[k]];
            count += way.folds_turned;
            for (const Way::Tab& tab : way.tabs)
                for (size_t j = 0; j < ways.size(); ++j) {
                    if (ways[j].empty())
                        continue;
                    const auto area = ways[j][choice[j]].areas.find(tab.code);
                    if (area == ways[j][choice[j]].areas.end())
                        continue;
                    const auto joint = tab.partners.find(area->second);
                    count +=
                        joint == tab.partners.end() ||
                        (joint->second != FoldDirection::unspecified && joint->second != tab.drawn);
                }
        }
        return count;
    };
    std::vector<size_t> choice(pieces_.size(), 0), best = choice;
    int fewest = misfits(choice);
    if (combinations <= 4096) {
        for (size_t n = 1; n < combinations && fewest > 0; ++n) {
            size_t rest = n;
            for (size_t k = 0; k < ways.size(); ++k) {
                const size_t count = std::max<size_t>(ways[k].size(), 1);
                choice[k] = rest % count;
                rest /= count;
            }
            if (const int m = misfits(choice); m < fewest) {
                fewest = m;
                best = choice;
            }
        }
    } else { // one piece at a time, in assembly order, until no piece turned round helps
        for (bool better = true; better && fewest > 0;) {
            better = false;
            for (size_t k = 0; k < ways.size(); ++k)
                for (size_t w = 0; w < ways[k].size(); ++w) {
                    choice = best;
                    choice[k] = w;
                    if (const int m = misfits(choice); m < fewest) {
                        fewest = m;
                        best = choice;
                        better = true;
                    }
                }
        }
    }
    for (size_t k = 0; k < pieces_.size(); ++k)
        if (pieces_[k].drawn)
            pieces_[k].placed = pieces_[k].candidates[best[k]];
}

void Verifier::fold_from(std::map<int, Pose>& from_sheet, const PieceCheck& piece, int start)
{
    std::deque<int> queue{start};
    while (!queue.empty()) {
        const int a = queue.front();
        queue.pop_front();
        for (const auto& [hinge_id, drawn] : piece.fold_of) {
            const Hinge& h = hinge(hinge_id);
            if (h.patch_a != a && h.patch_b != a)
                continue;
            const int b = h.patch_a == a ? h.patch_b : h.patch_a;
            if (from_sheet.count(b))
                continue;
            const DrawnFold& f = piece.drawn->folds[size_t(drawn)];
            const Vec3 axis = lift(f.to - f.from).normalized();
            // As designed, b turned about the drawn crease; the other way if drawn so.
            const Pose design = inverse(piece.sheet_pose.at(b)).then(piece.sheet_pose.at(a));
            double angle = angle_about(design.rotation, axis);
            if (piece.fold_turned.at(hinge_id))
                angle = -angle;
            from_sheet[b] = turn_about(lift(f.from), axis, angle).then(from_sheet.at(a));
            queue.push_back(b);
        }
    }
}

// Brings `moving` (a patch of a piece not yet placed) onto `fixed`: its crease edge laid onto
// the fixed edge, then turned about it by the design's joint angle. Of the two ways round the
// edge, the one nearer the design's relative pose is the way the tab goes on.
void Verifier::join(std::map<int, Pose>& from_sheet, int moving, const PieceCheck& moving_piece,
                    std::array<Vec2, 2> moving_edge, int fixed, const PieceCheck& fixed_piece,
                    std::array<Vec2, 2> fixed_edge)
{
    // moving sheet → design state → fixed sheet.
    const Pose relative =
        inverse(moving_piece.sheet_pose.at(moving)).then(fixed_piece.sheet_pose.at(fixed));
    Pose best;
    double best_gap = 1e300;
    for (int way = 0; way < 2; ++way) {
        if (way == 1)
            std::swap(moving_edge[0], moving_edge[1]);
        const Vec2 from_dir = moving_edge[1] - moving_edge[0];
        const Vec2 onto_dir = fixed_edge[1] - fixed_edge[0];
        Pose onto = turn_about(Vec3::Zero(), Vec3::UnitZ(),
                               std::atan2(onto_dir.y(), onto_dir.x()) -
                                   std::atan2(from_dir.y(), from_dir.x()));
        onto.translation = lift(fixed_edge[0]) - onto.rotation * lift(moving_edge[0]);
        const Pose rest = inverse(onto).then(relative);
        const Vec3 axis = lift(onto_dir).normalized();
        const Pose joint =
            onto.then(turn_about(lift(fixed_edge[0]), axis, angle_about(rest.rotation, axis)));
        const double gap = pose_gap(joint, relative, s_.size());
        if (gap < best_gap) {
            best_gap = gap;
            best = joint;
        }
    }
    from_sheet[moving] = best.then(from_sheet.at(fixed));
}

bool Verifier::place(std::map<int, Pose>& from_sheet)
{
    PieceCheck& card = pieces_.front();
    from_sheet[s_.ground] = inverse(card.sheet_pose.at(s_.ground));
    fold_from(from_sheet, card, s_.ground);
    for (size_t k = 1; k < pieces_.size(); ++k) {
        const PieceCheck& piece = pieces_[k];
        int start = -1;
        for (const DrawnTab& t : tabs_) {
            const DrawnArea& area = areas_.at(t.code);
            const PieceCheck& carrier = pieces_[t.piece];
            const DrawnFold& crease = carrier.drawn->folds[size_t(t.crease)];
            const std::array<Vec2, 2> crease_edge{crease.from, crease.to};
            const std::array<Vec2, 2> glue_edge{area.glue->polygon[0], area.glue->polygon[1]};
            if (t.piece == k && from_sheet.count(area.patch)) {
                join(from_sheet, t.patch, piece, crease_edge, area.patch, pieces_[area.piece],
                     glue_edge);
                start = t.patch;
            } else if (area.piece == k && t.piece != k && from_sheet.count(t.patch)) {
                join(from_sheet, area.patch, piece, glue_edge, t.patch, carrier, crease_edge);
                start = area.patch;
            }
            if (start >= 0)
                break;
        }
        if (start < 0) {
            error(DiagnosticCode::round_trip_unplaced,
                  piece.id + " has no glue tab joining it to a piece placed before it",
                  piece.local.flat.patches);
            return false;
        }
        fold_from(from_sheet, piece, start);
    }
    for (const PieceCheck& piece : pieces_)
        for (int id : piece.local.flat.patches)
            if (!from_sheet.count(id)) {
                error(DiagnosticCode::round_trip_unplaced,
                      piece.id + ": patch " + patch_name(s_, id) +
                          " is joined to the rest by no fold line",
                      {id});
                return false;
            }
    return true;
}

RoundTrip Verifier::compare(const std::map<int, Pose>& from_sheet)
{
    RoundTrip out;
    out.tolerance = tol_;
    // The re-made card: every patch is its drawn face, every hinge its drawn line, re-folded.
    Scaffold remade = s_;
    std::string worst_where;
    auto note = [&](double gap, const std::string& where) {
        if (gap > out.max_error) {
            out.max_error = gap;
            worst_where = where;
        }
    };
    for (const PieceCheck& piece : pieces_)
        for (const auto& [id, face] : piece.face_of) {
            const Pose& f = from_sheet.at(id);
            const Region& drawn = piece.drawn->faces[size_t(face)];
            Patch& p = remade.patches[size_t(remade.patch_index(id))];
            // A slit's slot cut across the patch's edge notches the face; the slit itself lies
            // on the paper, so the notch is left out.
            std::vector<std::array<Vec2, 2>> slits;
            for (const Slit& sl : s_.slits)
                if (piece.local.has(sl.patch_cut)) { // a slot on a fold notches both sides
                    const Vec3 a = piece.sheet_pose.at(sl.patch_cut).apply(sl.from);
                    const Vec3 b = piece.sheet_pose.at(sl.patch_cut).apply(sl.to);
                    slits.push_back({Vec2(a.x(), a.y()), Vec2(b.x(), b.y())});
                }
            p.outer.clear();
            for (const Vec2& q : drawn.outer)
                if (std::none_of(slits.begin(), slits.end(), [&](const auto& sl) {
                        return distance_to_segment(q, sl[0], sl[1]) <
                               1.01 * s_.paper_thickness + tol_;
                    }))
                    p.outer.push_back(f.apply(lift(q)));
            // The drawn holes, less the slots cut for slits (the slit lies on the paper).
            p.holes.clear();
            for (const Loop2& h : drawn.holes) {
                bool slot = false;
                for (const Slit& sl : s_.slits)
                    if (sl.patch_cut == id) {
                        const Vec3 mid = piece.sheet_pose.at(id).apply(0.5 * (sl.from + sl.to));
                        slot = slot || point_in_polygon(h, Vec2(mid.x(), mid.y()));
                    }
                if (slot)
                    continue;
                Loop3 hole;
                for (const Vec2& q : h)
                    hole.push_back(f.apply(lift(q)));
                p.holes.push_back(std::move(hole));
            }
            // Loops run counter-clockwise seen from the patch's normal side (its folds' flat
            // branch is read from it): a piece printed on its back lies the other way up.
            const Patch& designed = s_.patches[size_t(s_.patch_index(id))];
            Vec3 newell = Vec3::Zero();
            for (size_t i = 0; i < p.outer.size(); ++i)
                newell += p.outer[i].cross(p.outer[(i + 1) % p.outer.size()]);
            if (newell.dot(designed.normal) < 0) {
                std::reverse(p.outer.begin(), p.outer.end());
                for (Loop3& hole : p.holes)
                    std::reverse(hole.begin(), hole.end());
            }
            note(loop_gap(p.outer, designed.outer),
                 piece.id + " patch " + patch_name(s_, id) + " at the design angle");
        }
    for (Hinge& h : remade.hinges) {
        for (const PieceCheck& piece : pieces_) {
            if (auto fold = piece.fold_of.find(h.id); fold != piece.fold_of.end()) {
                const DrawnFold& line = piece.drawn->folds[size_t(fold->second)];
                h.from = from_sheet.at(h.patch_a).apply(lift(line.from));
                h.to = from_sheet.at(h.patch_a).apply(lift(line.to));
            }
        }
        for (const DrawnTab& t : tabs_)
            if (t.hinge == h.id) {
                const DrawnFold& line = pieces_[t.piece].drawn->folds[size_t(t.crease)];
                h.from = from_sheet.at(t.patch).apply(lift(line.from));
                h.to = from_sheet.at(t.patch).apply(lift(line.to));
            }
    }

    // A drawn fold within fold_snap of its designed line is put onto that line (each end to its
    // foot on it; along the line the drawing's ends stay). The drawing's last digits (a DXF
    // re-saved at 6 decimals moves a fold by up to 5e-7 mm) otherwise tilt the parallel folds of
    // a box fold, an over-constrained linkage that then locks a few degrees after the design
    // angle (docs/DESIGN.md, "popup verify and a drawing's last digits").
    for (size_t i = 0; i < remade.hinges.size(); ++i) {
        Hinge& h = remade.hinges[i];
        const Hinge& d = s_.hinges[i];
        const Vec3 u = d.to - d.from;
        if (u.norm() < 1e-12)
            continue;
        const Vec3 n = u.normalized();
        auto foot = [&](const Vec3& x) { return Vec3(d.from + (x - d.from).dot(n) * n); };
        if ((h.from - foot(h.from)).norm() <= fold_snap &&
            (h.to - foot(h.to)).norm() <= fold_snap) {
            h.from = foot(h.from);
            h.to = foot(h.to);
        }
    }

    SimulationOptions simulation;
    simulation.cancel = options_.cancel;
    const Result<FoldSweep> refolded = simulate_fold(remade, angles_, simulation);
    if (!refolded.ok) {
        const Diagnostics& why = refolded.diagnostics;
        const std::string message =
            "the card re-made from the sheets does not simulate: " +
            (why.empty() ? std::string("no reason given") : why.front().message);
        const std::vector<int> patches = why.empty() ? std::vector<int>{} : why.front().patches;
        if (has_errors(findings_)) // a consequence of what is named above, not a finding of its own
            findings_.push_back(Diagnostic::warning(DiagnosticCode::round_trip_failed,
                                                    message + " (it follows from the errors above)",
                                                    about_patches(patches)));
        else
            error(DiagnosticCode::round_trip_failed, message, patches);
        return out;
    }
    const auto& a = designed_.value.states;
    const auto& b = refolded.value.states;
    for (size_t k = 0; k < std::min(a.size(), b.size()); ++k) {
        if (std::abs(a[k].angle - b[k].angle) > 1e-12)
            break;
        // The fold-direction samples among them count as checks, not as angles asked for.
        const bool asked = std::any_of(asked_.begin(), asked_.end(),
                                       [&](double x) { return std::abs(x - a[k].angle) < 1e-9; });
        out.angles += asked;
        for (size_t i = 0; i < s_.patches.size(); ++i) {
            if (remade.patches[i].outer.empty())
                continue;
            std::ostringstream where;
            where << "patch " << patch_name(s_, s_.patches[i].id) << " at "
                  << std::round(a[k].angle * 180.0 / M_PI * 10.0) / 10.0 << "°";
            note(loop_gap(posed_outline(s_.patches[i], a[k].poses[i]),
                          posed_outline(remade.patches[i], b[k].poses[i])),
                 where.str());
        }
    }
    out.ok = out.max_error <= out.tolerance && out.angles == int(asked_.size());
    if (!out.ok) {
        std::ostringstream m;
        m << "the card folded from the sheets misses the design by " << millimetres(out.max_error)
          << " (tolerance " << millimetres(out.tolerance) << "), worst at " << worst_where
          << ", over " << out.angles << " of " << asked_.size() << " fold angles";
        error(DiagnosticCode::round_trip_mismatch, m.str());
    }
    return out;
}

} // namespace

Result<RoundTrip> verify_sheets(const Scaffold& design, const std::vector<SheetDrawing>& drawings,
                                const VerifyOptions& options)
{
    Result<RoundTrip> r;
    if (options.angles < 2 || options.angles > 361)
        r.fail(DiagnosticCode::bad_option,
               "angles = " + std::to_string(options.angles) + ", must be 2 to 361",
               about_parameter("angles"));
    Result<Scaffold> checked = validate_scaffold(design);
    if (!checked.ok) {
        r.fail_with(checked.diagnostics);
        return r;
    }
    const Scaffold& s = checked.value;
    r.value.tolerance = 1e-6 * s.size();
    Result<std::vector<DrawnPiece>> drawn = read_drawn_pieces(drawings, r.diagnostics);
    if (!drawn.ok) {
        r.ok = false;
        r.diagnostics.insert(r.diagnostics.end(), drawn.diagnostics.begin(),
                             drawn.diagnostics.end());
    }
    if (!r.ok)
        return r;
    Verifier verifier(s, options, r.diagnostics);
    if (!verifier.prepare(r))
        return r;
    verifier.match(drawn.value);
    verifier.check_tabs();
    std::map<int, Pose> from_sheet;
    if (!verifier.structural && verifier.place(from_sheet))
        r.value = verifier.compare(from_sheet);
    r.value.tolerance = 1e-6 * s.size();
    r.value.ok = r.value.ok && !has_errors(r.diagnostics);
    return r;
}

} // namespace popup
