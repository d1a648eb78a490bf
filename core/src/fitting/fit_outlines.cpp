#include "popup/fitting/fit_outlines.hpp"

#include "../geometry/clipper_paths.hpp"
#include "../geometry/polygon_2d.hpp"
#include "../geometry/snap_onto_lines.hpp"
#include "../model/millimetres.hpp"
#include "fold_bridges.hpp"
#include "glued_joints.hpp"
#include "outline_support.hpp"
#include "projected_faces.hpp"
#include "silhouette_cache.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "popup/model/apply_profile.hpp"
#include "popup/model/profile.hpp"
#include "popup/sheets/sheet_layout.hpp"
#include "popup/simulation/check_validity.hpp"
#include "popup/simulation/simulate_fold.hpp"

namespace popup {

using glued_joints::joint_lengths;
using glued_joints::joints_without_room;
using outline_support::first_error;
using outline_support::placed;
using outline_support::record_cut;
namespace {

/// `part` is `prefix`, or `prefix` followed by a number (stacked box end panels: FL1, FL2...).
bool is_part(const std::string& part, const std::string& prefix)
{
    if (part.rfind(prefix, 0) != 0)
        return false;
    return std::all_of(part.begin() + long(prefix.size()), part.end(),
                       [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; });
}

/// One principal part: its patch id and its part name.
struct Part {
    int patch = -1;
    std::string name;
};

/// The mechanism's principal parts in `s`, sorted by part name: the order in which the
/// workbench applies a feature's profiles (popupwb.profiles.apply_profiles), so each frame is
/// measured on the same paper in both places.
std::vector<Part> parts_of(const Scaffold& s, const FittedMechanism& m,
                           const std::vector<std::string>& prefixes)
{
    std::vector<Part> out;
    const std::string prefix = m.name + ".";
    for (const Patch& p : s.patches) {
        if (p.name.rfind(prefix, 0) != 0)
            continue;
        const std::string part = p.name.substr(prefix.size());
        for (const std::string& principal : prefixes)
            if (is_part(part, principal)) {
                out.push_back({p.id, part});
                break;
            }
    }
    std::sort(out.begin(), out.end(), [](const Part& a, const Part& b) { return a.name < b.name; });
    return out;
}

/// Extent of a patch along u and v of its profile frame (popupwb.profiles.part_size).
Vec2 size_in(const Patch& patch, const ProfileFrame& f)
{
    Vec2 lo(1e300, 1e300), hi(-1e300, -1e300);
    for (const Vec3& x : patch.outer) {
        const Vec2 q = f.to_frame(x);
        lo = lo.cwiseMin(q);
        hi = hi.cwiseMax(q);
    }
    return hi - lo;
}

/// A step whose riser and tread are parallel lies flat: it stands as the model does when its
/// host is at a right angle, which for a host flat at 180° is the card open at 90°.
bool lies_flat(const Scaffold& s, const FittedMechanism& m)
{
    if (m.kind != MechanismKind::step_fold)
        return false;
    const Patch* riser = nullptr;
    const Patch* tread = nullptr;
    for (const Patch& p : s.patches) {
        if (p.name == m.name + ".riser")
            riser = &p;
        if (p.name == m.name + ".tread")
            tread = &p;
    }
    if (!riser || !tread)
        return false;
    Patch a = *riser, b = *tread;
    a.derive_frame();
    b.derive_frame();
    return std::abs(a.normal.dot(b.normal)) > 1.0 - 1e-6;
}

/// Cuts narrower than this (mm) are the fit's round-off, not the model's outline: the sheets'
/// smallest feature (SheetOptions::min_feature, 3 mm) is twice it.
constexpr double kSmallestCut = 1.5;
constexpr double kCleanDistance =
    1e-3; ///< mm: outline vertices this near their neighbours' line go
/// Paper narrower than twice this (mm) goes from an outline: no cutter makes it.
constexpr double kFinestPaper = 0.25;
/// Narrowest bridge (mm) that holds a part on a fold its silhouette leaves: twice the sheets'
/// smallest feature, so the cut on either side of it can be made.
constexpr double kBridgeWidth = 4 * kSmallestCut;

/// `patch`'s paper (its outline minus its holes) in `frame`.
ClipperLib::Paths paper_of(const Patch& patch, const ProfileFrame& frame)
{
    using namespace ClipperLib;
    Loop2 outline;
    for (const Vec3& x : patch.outer)
        outline.push_back(frame.to_frame(x));
    std::vector<Loop2> holes;
    for (const Loop3& h : patch.holes) {
        Loop2 l;
        for (const Vec3& x : h)
            l.push_back(frame.to_frame(x));
        holes.push_back(l);
    }
    Paths paper = counter_clockwise_paths({outline});
    if (!holes.empty()) {
        Clipper c;
        c.AddPaths(paper, ptSubject, true);
        c.AddPaths(counter_clockwise_paths(holes), ptClip, true);
        c.Execute(ctDifference, paper, pftNonZero, pftNonZero);
    }
    return paper;
}

/// The region `profile` covers (its outer loop minus its holes).
ClipperLib::Paths region_of(const Profile& profile)
{
    using namespace ClipperLib;
    Paths shape = counter_clockwise_paths({profile.outer});
    if (!profile.holes.empty()) {
        Clipper c;
        c.AddPaths(shape, ptSubject, true);
        c.AddPaths(counter_clockwise_paths(profile.holes), ptClip, true);
        c.Execute(ctDifference, shape, pftNonZero, pftNonZero);
    }
    return shape;
}

/// `paths` grown by `r` mm (shrunk when negative), corners mitred.
ClipperLib::Paths grown(const ClipperLib::Paths& paths, double r)
{
    ClipperLib::Paths out;
    ClipperLib::ClipperOffset o(4.0);
    o.AddPaths(paths, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
    o.Execute(out, r * clipper_scale);
    return out;
}

/// `left` (Clipper paths, within the patch's `paper`) without its notches and spikes narrower than
/// 2·kFinestPaper, as a tree: a scanned model's silhouette leaves some a tenth of a millimetre
/// across. The kerf takes them, and the sheets' check then finds the design's corner at their tip
/// off the cut piece. A closing then an opening, each kept within what it started from.
ClipperLib::PolyTree without_hairs(const ClipperLib::Paths& left, const ClipperLib::Paths& paper)
{
    using namespace ClipperLib;
    // Around the patch counts as paper: the next patch across a fold is, and a notch that meets
    // the fold at a sharp angle is as thin there as one within the patch.
    Paths around;
    Clipper c;
    c.AddPaths(grown(paper, 4 * kFinestPaper), ptSubject, true);
    c.AddPaths(paper, ptClip, true);
    c.Execute(ctDifference, around, pftNonZero, pftNonZero);
    c.Clear();
    c.AddPaths(left, ptSubject, true);
    c.AddPaths(around, ptClip, true);
    c.Execute(ctUnion, around, pftNonZero, pftNonZero);
    c.Clear();
    Paths closed;
    c.AddPaths(grown(grown(around, kFinestPaper), -kFinestPaper), ptSubject, true);
    c.AddPaths(paper, ptClip, true);
    c.Execute(ctIntersection, closed, pftNonZero, pftNonZero);
    c.Clear();
    PolyTree out;
    c.AddPaths(grown(grown(closed, -kFinestPaper), kFinestPaper), ptSubject, true);
    c.AddPaths(closed, ptClip, true);
    c.Execute(ctIntersection, out, pftNonZero, pftNonZero);
    return out;
}

/// `paper` minus the parts of the region `shape` cuts away that are wider than 2·kSmallestCut
/// (a morphological opening of the cut-away region, exact on Clipper's grid): slivers between
/// a fitted part and a model a little smaller, and thin notches, stay paper. Its largest piece
/// with its holes, named `name` (apply_profile drops pieces without folds anyway); empty when
/// nothing is left to cut.
std::optional<Profile> significant_cut(const ClipperLib::Paths& paper,
                                       const ClipperLib::Paths& shape, const std::string& name)
{
    using namespace ClipperLib;
    Paths away;
    {
        Clipper c;
        c.AddPaths(paper, ptSubject, true);
        c.AddPaths(shape, ptClip, true);
        c.Execute(ctDifference, away, pftNonZero, pftNonZero);
    }
    const double r = kSmallestCut * clipper_scale;
    Paths eroded, opened;
    {
        ClipperOffset o(4.0);
        o.AddPaths(away, jtMiter, etClosedPolygon);
        o.Execute(eroded, -r);
    }
    if (eroded.empty())
        return std::nullopt;
    {
        ClipperOffset o(4.0);
        o.AddPaths(eroded, jtMiter, etClosedPolygon);
        o.Execute(opened, r);
    }
    // Growing back with mitred corners can reach past the region where an edge shorter than r
    // vanished in the shrink (a strip's end next to a slanted silhouette): what is cut stays
    // within what the shape leaves, so the shape is always kept.
    Paths left;
    {
        Clipper c;
        c.AddPaths(opened, ptSubject, true);
        c.AddPaths(away, ptClip, true);
        c.Execute(ctIntersection, opened, pftNonZero, pftNonZero);
        c.Clear();
        c.AddPaths(paper, ptSubject, true);
        c.AddPaths(opened, ptClip, true);
        c.Execute(ctDifference, left, pftNonZero, pftNonZero);
    }
    const PolyTree kept = without_hairs(left, paper);
    const PolyNode* best = nullptr;
    double best_area = 0;
    for (const PolyNode* n : kept.Childs) {
        const double a = std::abs(path_area(n->Contour));
        if (a > best_area) {
            best_area = a;
            best = n;
        }
    }
    if (!best)
        return std::nullopt;
    // Vertices within a micrometre of their neighbours' line go (CleanPolygon): where a strip
    // meets the silhouette such a vertex left an edge the sheets, which draw and re-read the
    // outline to that precision, found 0.6 µm off the design. The area moves by at most the
    // perimeter times a micrometre.
    auto cleaned = [](ClipperLib::Path path) {
        ClipperLib::CleanPolygon(path, kCleanDistance * clipper_scale);
        return to_loop(path);
    };
    Profile out;
    out.name = name;
    out.outer = cleaned(best->Contour);
    for (const PolyNode* h : best->Childs)
        out.holes.push_back(cleaned(h->Contour));
    return out;
}

/// `cut` with the paper `kept` united into it, cut again (significant_cut); `cut` when `kept`
/// is empty.
std::optional<Profile> with_kept(const ClipperLib::Paths& paper, const Profile& cut,
                                 const ClipperLib::Paths& kept)
{
    using namespace ClipperLib;
    if (kept.empty())
        return cut;
    Paths shape;
    Clipper c;
    c.AddPaths(region_of(cut), ptSubject, true);
    c.AddPaths(kept, ptClip, true);
    c.Execute(ctUnion, shape, pftNonZero, pftNonZero);
    return significant_cut(paper, shape, cut.name);
}

/// `loop` with each edge whose two ends lie within `reach` of one of `lines` put onto that line
/// (a vertex on two such lines, at their crossing). Lone vertices near a line stay: put on it,
/// they would touch the next patch at a point, outside any fold.
void edges_onto_lines(Loop2& loop, const std::vector<std::array<Vec2, 2>>& lines, double reach)
{
    const size_t n = loop.size();
    std::vector<std::vector<const std::array<Vec2, 2>*>> on(n);
    for (size_t i = 0; i < n; ++i) {
        const size_t j = (i + 1) % n;
        for (const auto& l : lines)
            if ((l[1] - l[0]).norm() > 0 && distance_to_segment(loop[i], l[0], l[1]) <= reach &&
                distance_to_segment(loop[j], l[0], l[1]) <= reach) {
                on[i].push_back(&l);
                on[j].push_back(&l);
            }
    }
    for (size_t i = 0; i < n; ++i) {
        if (on[i].empty())
            continue;
        SnapTargets targets;
        for (const auto* l : on[i])
            targets.lines.push_back(*l);
        Loop2 one{loop[i]};
        snap_onto_lines(one, targets, reach);
        loop[i] = one.front();
    }
    loop.erase(std::unique(loop.begin(), loop.end()), loop.end());
    while (loop.size() > 1 && loop.front() == loop.back())
        loop.pop_back();
}

/// `cut` with each edge within 2·kCleanDistance of the patch's edges, folds and slits put
/// exactly onto them: the cleaning in significant_cut can leave a stretch along a fold slanted a
/// micrometre off it, farther than apply_profile's tolerance, which then finds no paper along
/// the fold and refuses the outline.
Profile onto_patch_lines(Profile cut, const Scaffold& s, int patch, const ProfileFrame& frame)
{
    std::vector<std::array<Vec2, 2>> lines;
    const Patch& p = *s.find_patch(patch);
    auto add_loop = [&](const Loop3& loop) {
        for (size_t i = 0; i < loop.size(); ++i)
            lines.push_back({frame.to_frame(loop[i]), frame.to_frame(loop[(i + 1) % loop.size()])});
    };
    add_loop(p.outer);
    for (const Loop3& h : p.holes)
        add_loop(h);
    for (const Hinge& h : s.hinges)
        if (h.patch_a == patch || h.patch_b == patch)
            lines.push_back({frame.to_frame(h.from), frame.to_frame(h.to)});
    for (const Slit& sl : s.slits)
        if (sl.patch_cut == patch)
            lines.push_back({frame.to_frame(sl.from), frame.to_frame(sl.to)});
    edges_onto_lines(cut.outer, lines, 2 * kCleanDistance);
    for (Loop2& h : cut.holes)
        edges_onto_lines(h, lines, 2 * kCleanDistance);
    return cut;
}

/// The outline part `patch` of `s` takes from `silhouette` (in `frame`): its significant cut;
/// where glued joints are kept (`crease` > 0) that cut again with the strips of paper its glued
/// joints need united into it (glued_joints::joint_strips, the default sheets' tab depth deep);
/// then, for each fold, joint or slit the cut meets along less than the sheets' smallest feature
/// (2·kSmallestCut), a bridge of paper from it to the
/// outline (fold_bridges::bridges, `crease` wide, at least kBridgeWidth), so the part stays on
/// it instead of losing its outline. Empty when nothing is left to cut.
std::optional<Profile> part_outline(const Scaffold& s, int patch, const ProfileFrame& frame,
                                    const Profile& silhouette, double crease)
{
    const ClipperLib::Paths paper = paper_of(*s.find_patch(patch), frame);
    std::optional<Profile> cut = significant_cut(paper, region_of(silhouette), silhouette.name);
    const double tab_depth = SheetOptions{}.tab_width;
    if (cut && crease > 0)
        cut = with_kept(
            paper, *cut,
            glued_joints::joint_strips(s, patch, frame, region_of(*cut), crease, tab_depth));
    if (cut)
        cut = with_kept(paper, *cut,
                        fold_bridges::bridges(s, patch, frame, paper, region_of(*cut),
                                              std::max(crease, kBridgeWidth), tab_depth,
                                              2 * kSmallestCut));
    if (cut)
        cut = onto_patch_lines(*cut, s, patch, frame);
    return cut;
}

/// Length of each fold and joint of `patch`, by the other patch's name, when the patch carries
/// a mechanism built after its own (a hinge to a patch whose name does not start with `own`
/// and whose id is larger); empty otherwise. Such a patch's folds must stay whole: the
/// workbench cuts a part before it builds what stands on it (card_scaffold.build), and the
/// later mechanism is built on the base pair's fold (one of these) and folds onto the part.
std::map<std::string, double> carried_folds(const Scaffold& s, int patch, const std::string& own)
{
    std::map<std::string, double> out;
    bool carries = false;
    for (const Hinge& h : s.hinges) {
        if (h.patch_a != patch && h.patch_b != patch)
            continue;
        const int other = h.patch_a == patch ? h.patch_b : h.patch_a;
        const Patch* p = s.find_patch(other);
        if (!p)
            continue;
        carries |= other > patch && p->name.rfind(own, 0) != 0;
        out[p->name] += (h.to - h.from).norm();
    }
    return carries ? out : std::map<std::string, double>{};
}

/// Applies one part's silhouette to `s`; the profile it kept (an empty part when the silhouette
/// covers the whole part: `s` unchanged), or why not.
Result<FittedProfile> outline_part(Scaffold& s, SilhouetteCache& silhouettes,
                                   const FittedMechanism& m, const Part& part, bool pose_at_90,
                                   double glued_joint)
{
    Result<FittedProfile> r;
    const Result<ProfileFrame> frame = profile_frame(s, part.patch);
    if (!frame.ok) {
        r.fail_with(frame.diagnostics);
        return r;
    }
    std::optional<Pose> pose;
    if (pose_at_90) {
        const Result<FoldSweep> sweep = simulate_fold(s, {M_PI / 2});
        if (!sweep.ok || sweep.value.states.empty()) {
            r.fail_with(sweep.diagnostics);
            if (r.ok)
                r.fail(DiagnosticCode::bad_profile, "the card could not be posed at 90°");
            return r;
        }
        pose = sweep.value.states.front().poses[size_t(s.patch_index(part.patch))];
    }
    const Patch& patch = *s.find_patch(part.patch);
    const Result<Silhouette> sil =
        silhouettes.seen_in(posed(frame.value, pose),
                            patch.name.empty() ? "patch " + std::to_string(patch.id) : patch.name);
    if (!sil.ok) {
        r.fail_with(sil.diagnostics);
        return r;
    }
    Profile silhouette = sil.value.profile;
    silhouette.name = "silhouette of the model";
    FittedProfile& fp = r.value;
    fp.mechanism = m.name;
    fp.part = part.name;
    fp.reference = size_in(*s.find_patch(part.patch), frame.value);
    const std::optional<Profile> wanted =
        part_outline(s, part.patch, frame.value, silhouette, glued_joint);
    if (!wanted) { // the part is the model's outline there, up to slivers
        fp.part.clear();
        return r;
    }
    const Profile& profile = *wanted;
    const std::map<std::string, double> carried = carried_folds(s, part.patch, m.name + ".");
    const std::map<std::string, double> joints_before = joint_lengths(s, part.patch);
    const std::set<std::string> no_room_before =
        joints_without_room(s, part.patch, SheetOptions{}.tab_width);
    Scaffold before = s;
    const Result<ProfileApplied> applied = apply_profile(s, part.patch, profile);
    if (!applied.ok) {
        r.fail_with(applied.diagnostics);
        return r;
    }
    // A part carrying a later mechanism keeps its folds whole (see carried_folds).
    const double tol = 1e-6 * std::max(1.0, fp.reference.maxCoeff());
    const std::map<std::string, double> left = carried_folds(s, part.patch, m.name + ".");
    for (const auto& [name, whole] : carried) {
        const double length = left.count(name) ? left.at(name) : 0.0;
        if (length < whole - tol) {
            s = std::move(before);
            r.fail(DiagnosticCode::bad_profile,
                   "it carries another mechanism, and the outline would shorten its fold with " +
                       name + " to " + std::to_string(length) + " of " + std::to_string(whole) +
                       " mm");
            return r;
        }
    }
    if (glued_joint > 0) {
        // Every glued joint of the part long enough for a glue tab keeps room for one on each of
        // its pieces. The strips (part_outline) see to it where the silhouette meets the joint
        // (a figure's feet, a wheel); this guards the rest: a joint the silhouette leaves entirely
        // is lost, and the sheets could not glue it. The crease is FitOptions.min_part_mm, by
        // default the sheets' shortest tabbed crease; 0 lets the maker glue by hand
        // (docs/DESIGN.md).
        const double crease = glued_joint;
        const std::map<std::string, double> joints_after = joint_lengths(s, part.patch);
        for (const auto& [name, whole] : joints_before) {
            const double length = joints_after.count(name) ? joints_after.at(name) : 0.0;
            if (whole >= crease - tol && length < crease - tol) { // tol: Clipper's rounding
                s = std::move(before);
                r.fail(DiagnosticCode::bad_profile,
                       "the outline would leave a piece of its glued joint with " + name + " " +
                           millimetres(length) + " long, shorter than the narrowest glue tab's " +
                           millimetres(crease));
                return r;
            }
        }
        // ... and keeps room inward for the default tab, whole, to land on it (narrowed tabs need
        // room too).
        const double tab_depth = SheetOptions{}.tab_width;
        for (const std::string& name : joints_without_room(s, part.patch, tab_depth))
            if (!no_room_before.count(name)) {
                s = std::move(before);
                r.fail(DiagnosticCode::bad_profile, "the outline would leave no room for a " +
                                                        millimetres(tab_depth) +
                                                        " glue tab along its joint with " + name);
                return r;
            }
    }
    // A silhouette covering the whole part changes nothing: no profile, so the part still
    // follows later edits of its mechanism's dimensions (a stored outline would clip them).
    if (std::abs(applied.value.area_after - applied.value.area_before) <=
        1e-6 * applied.value.area_before) {
        s = std::move(before);
        fp.part.clear();
        return r;
    }
    const Patch& cut = *s.find_patch(part.patch);
    record_cut(fp, cut, applied.value);
    return r;
}

} // namespace

std::vector<std::string> principal_parts(MechanismKind kind)
{
    switch (kind) {
    case MechanismKind::box_fold:
        return {"L", "R", "TG", "TB", "FL", "FR", "BL", "BR"};
    case MechanismKind::tent_fold:
        return {"slope_ground", "slope_backdrop"};
    case MechanismKind::step_fold:
        return {"riser", "tread"};
    case MechanismKind::v_fold:
        return {"wing_ground", "wing_backdrop"};
    default:
        return {};
    }
}

namespace {

/// One mechanism's outlines (fit_outlines' loop body): together when the check passes, else one
/// at a time, keeping what the simulator accepts.
void outline_mechanism(OutlineOutcome& out, SilhouetteCache& silhouettes, const FittedMechanism& m,
                       const std::vector<std::string>& prefixes, bool pose_at_90,
                       double glued_joint, const CancelFlag* cancel)
{
    ValidityOptions vo;
    vo.cancel = cancel;
    stop_if_cancelled(cancel, "outlines");
    const std::vector<Part> parts = parts_of(out.scaffold, m, prefixes);
    if (parts.empty())
        return;
    // All of the mechanism's outlines at once: one check when they agree.
    Scaffold together = out.scaffold;
    std::vector<FittedProfile> kept;
    bool all_applied = true;
    for (const Part& part : parts) {
        Result<FittedProfile> fp =
            outline_part(together, silhouettes, m, part, pose_at_90, glued_joint);
        if (!fp.ok) {
            all_applied = false;
            break;
        }
        if (!fp.value.part.empty())
            kept.push_back(fp.value);
    }
    if (all_applied && check_validity(together, vo).valid()) {
        out.scaffold = together;
        for (const FittedProfile& fp : kept)
            out.profiles.push_back(fp);
        return;
    }
    // One at a time: keep what the simulator accepts.
    for (const Part& part : parts) {
        Scaffold trial = out.scaffold;
        Result<FittedProfile> fp =
            outline_part(trial, silhouettes, m, part, pose_at_90, glued_joint);
        if (!fp.ok) {
            out.dropped.push_back(
                {m.name, "profile dropped",
                 part.name + ": " + first_error(fp.diagnostics, "it could not be applied")});
            continue;
        }
        if (fp.value.part.empty())
            continue; // the part is already the model's outline there
        const ValidityReport report = check_validity(trial, vo);
        if (!report.valid()) {
            out.dropped.push_back({m.name, "profile dropped",
                                   part.name + ": the validity check failed with it: " +
                                       first_error(report.diagnostics, "not valid")});
            continue;
        }
        out.scaffold = trial;
        out.profiles.push_back(fp.value);
    }
}

} // namespace

OutlineOutcome fit_outlines(const ModelMesh& model_in_card, const Scaffold& scaffold,
                            const std::vector<FittedMechanism>& mechanisms,
                            const CancelFlag* cancel, double glued_joint_mm)
{
    OutlineOutcome out;
    out.scaffold = scaffold;
    SilhouetteCache silhouettes(model_in_card);
    for (const FittedMechanism& m : mechanisms)
        outline_mechanism(out, silhouettes, m, principal_parts(m.kind), lies_flat(out.scaffold, m),
                          glued_joint_mm, cancel);
    return out;
}

OutlineOutcome fit_outlines_of(const ModelMesh& model_in_card, const Scaffold& scaffold,
                               const FittedMechanism& mechanism,
                               const std::vector<std::string>& parts, const CancelFlag* cancel)
{
    OutlineOutcome out;
    out.scaffold = scaffold;
    SilhouetteCache silhouettes(model_in_card);
    outline_mechanism(out, silhouettes, mechanism, parts, false,
                      shortest_tabbed_crease(SheetOptions{}), cancel);
    return out;
}

OutlineOutcome fit_outlines_for(const ModelMesh& model, const Eigen::Matrix4d& model_to_card,
                                const Scaffold& scaffold,
                                const std::vector<FittedMechanism>& mechanisms,
                                const CancelFlag* cancel, double glued_joint_mm)
{
    return fit_outlines(placed(model, model_to_card), scaffold, mechanisms, cancel, glued_joint_mm);
}

} // namespace popup
