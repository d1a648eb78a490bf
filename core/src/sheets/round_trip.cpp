#include "round_trip.hpp"

#include <cmath>
#include <deque>
#include <map>
#include <sstream>

#include "popup/simulation/simulate_fold.hpp"

namespace popup::sheets {

namespace {

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

struct Rebuilt {
    std::map<int, Pose> from_sheet; // patch id → sheet (z = 0) to design state, re-folded
    std::map<int, std::pair<Vec2, Vec2>> crease; // hinge id → its line on the sheets
    std::map<int, int> crease_patch;             // hinge id → the patch whose sheet it is on
};

} // namespace

RoundTrip round_trip(const Scaffold& s, const SheetSet& sheets, const std::vector<Pose>& to_sheet,
                     const Result<FoldSweep>& designed, const std::vector<double>& angles,
                     Diagnostics& diagnostics)
{
    RoundTrip result;
    result.tolerance = 1e-6 * sheets.card_size;
    auto sheet_pose = [&](int patch) { return to_sheet[s.patch_index(patch)]; };
    std::map<int, const Hinge*> hinge;
    for (const Hinge& h : s.hinges)
        hinge[h.id] = &h;

    Rebuilt re;
    for (const SheetPiece& piece : sheets.pieces) {
        for (const FoldLine& f : piece.folds)
            if (f.kind == JointKind::fold) {
                re.crease[f.hinge] = {f.from, f.to};
                re.crease_patch[f.hinge] = hinge.at(f.hinge)->patch_a;
            }
        for (const GlueTab& t : piece.tabs) {
            re.crease[t.hinge] = {t.polygon[0], t.polygon[1]};
            re.crease_patch[t.hinge] = t.patch;
        }
    }
    // Folds a piece from one patch already placed: each neighbour turns about their crease.
    auto fold_from = [&](const SheetPiece& piece, int start) {
        std::deque<int> queue{start};
        while (!queue.empty()) {
            const int a = queue.front();
            queue.pop_front();
            for (const FoldLine& f : piece.folds) {
                const Hinge& h = *hinge.at(f.hinge);
                if (f.kind != JointKind::fold || (h.patch_a != a && h.patch_b != a))
                    continue;
                const int b = h.patch_a == a ? h.patch_b : h.patch_a;
                if (re.from_sheet.count(b))
                    continue;
                const Vec3 axis = lift(f.to - f.from).normalized();
                const Pose design = inverse(sheet_pose(b)).then(sheet_pose(a));
                const Pose fold =
                    turn_about(lift(f.from), axis, angle_about(design.rotation, axis));
                re.from_sheet[b] = fold.then(re.from_sheet.at(a));
                queue.push_back(b);
            }
        }
    };

    re.from_sheet[s.ground] = inverse(sheet_pose(s.ground));
    fold_from(sheets.pieces.front(), s.ground);
    // Brings a patch of a new piece onto one already re-folded: its crease edge (on its sheet)
    // laid onto the matching edge of the other's glue area or tab, then turned by the joint.
    auto join = [&](int moving, const Loop2& moving_edge, int fixed, const Loop2& fixed_edge) {
        const Vec2 from_dir = moving_edge[1] - moving_edge[0];
        const Vec2 onto_dir = fixed_edge[1] - fixed_edge[0];
        Pose onto = turn_about(Vec3::Zero(), Vec3::UnitZ(),
                               std::atan2(onto_dir.y(), onto_dir.x()) -
                                   std::atan2(from_dir.y(), from_dir.x()));
        onto.translation = lift(fixed_edge[0]) - onto.rotation * lift(moving_edge[0]);
        const Pose design = inverse(sheet_pose(moving)).then(sheet_pose(fixed));
        const Pose rest = inverse(onto).then(design);
        const Vec3 axis = lift(onto_dir).normalized();
        const Pose joint =
            onto.then(turn_about(lift(fixed_edge[0]), axis, angle_about(rest.rotation, axis)));
        re.from_sheet[moving] = joint.then(re.from_sheet.at(fixed));
    };
    auto glue_area = [&](const GlueTab& t) -> const GlueArea* {
        for (const GlueArea& g : sheets.pieces[t.target_piece].glue)
            if (g.code == t.code)
                return &g;
        return nullptr;
    };
    for (size_t k = 1; k < sheets.pieces.size(); ++k) {
        const SheetPiece& piece = sheets.pieces[k];
        int start = -1;
        for (const GlueTab& t : piece.tabs) // its own tab onto a piece in place
            if (const GlueArea* g = glue_area(t);
                start < 0 && g && re.from_sheet.count(t.target_patch)) {
                join(t.patch, t.polygon, t.target_patch, g->polygon);
                start = t.patch;
            }
        for (size_t j = 0; j < k && start < 0; ++j) // a tab of a piece in place onto it
            for (const GlueTab& t : sheets.pieces[j].tabs)
                if (const GlueArea* g = glue_area(t);
                    start < 0 && g && size_t(t.target_piece) == k && re.from_sheet.count(t.patch)) {
                    join(t.target_patch, g->polygon, t.patch, t.polygon);
                    start = t.target_patch;
                }
        if (start < 0) {
            std::vector<int> ids;
            for (const FlatPatch& p : piece.patches)
                ids.push_back(p.id);
            diagnostics.push_back(
                Diagnostic::error(DiagnosticCode::round_trip_unplaced,
                                  "round trip: " + piece.id +
                                      " has no glue tab joining it to a piece placed before it",
                                  about_patches(ids)));
            return result;
        }
        fold_from(piece, start);
    }

    // Static: every patch of the sheets, re-folded, against the design state.
    Scaffold remade = s;
    for (const SheetPiece& piece : sheets.pieces)
        for (const FlatPatch& fp : piece.patches) {
            const Pose& f = re.from_sheet.at(fp.id);
            Patch& p = remade.patches[remade.patch_index(fp.id)];
            for (size_t i = 0; i < fp.outer.size(); ++i) {
                p.outer[i] = f.apply(lift(fp.outer[i]));
                result.max_error =
                    std::max(result.max_error, (p.outer[i] - s.find_patch(fp.id)->outer[i]).norm());
            }
            for (size_t j = 0; j < fp.holes.size(); ++j)
                for (size_t i = 0; i < fp.holes[j].size(); ++i)
                    p.holes[j][i] = f.apply(lift(fp.holes[j][i]));
        }
    for (Hinge& h : remade.hinges) {
        auto line = re.crease.find(h.id);
        if (line == re.crease.end())
            continue; // a joint whose tab found no room keeps the design's line
        const Pose& f = re.from_sheet.at(re.crease_patch.at(h.id));
        h.from = f.apply(lift(line->second.first));
        h.to = f.apply(lift(line->second.second));
    }

    // Through the simulator: the re-made card against the design over the sweep.
    Result<FoldSweep> refolded = simulate_fold(remade, angles);
    if (!refolded.ok || !designed.ok) {
        const Diagnostics& why = refolded.ok ? designed.diagnostics : refolded.diagnostics;
        diagnostics.push_back(Diagnostic::error(
            DiagnosticCode::round_trip_failed,
            std::string("round trip: the ") + (refolded.ok ? "design" : "re-folded card") +
                " does not simulate: " +
                (why.empty() ? std::string("no reason given") : why.front().message),
            why.empty() ? DiagnosticSubject{} : about_patches(why.front().patches)));
        return result;
    }
    const auto& a = designed.value.states;
    const auto& b = refolded.value.states;
    for (size_t k = 0; k < std::min(a.size(), b.size()); ++k) {
        if (std::abs(a[k].angle - b[k].angle) > 1e-12)
            break;
        ++result.angles;
        for (size_t i = 0; i < s.patches.size(); ++i)
            for (size_t v = 0; v < s.patches[i].outer.size(); ++v)
                result.max_error =
                    std::max(result.max_error, (a[k].poses[i].apply(s.patches[i].outer[v]) -
                                                b[k].poses[i].apply(remade.patches[i].outer[v]))
                                                   .norm());
    }
    result.ok = result.max_error <= result.tolerance && result.angles == int(a.size());
    if (!result.ok) {
        std::ostringstream m;
        m << "round trip: the re-folded sheets miss the design by " << result.max_error
          << " mm (tolerance " << result.tolerance << " mm) over " << result.angles << " angles";
        diagnostics.push_back(Diagnostic::error(DiagnosticCode::round_trip_mismatch, m.str()));
    }
    return result;
}

} // namespace popup::sheets
