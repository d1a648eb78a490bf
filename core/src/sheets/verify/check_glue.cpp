#include "check_glue.hpp"

#include <algorithm>
#include <set>

#include "../../model/millimetres.hpp"
#include "fold_sides.hpp"

namespace popup::sheets {

namespace {

using AreasByCode = std::map<std::string, std::vector<DrawnArea>>;

// Every glue area by its code, with the patch it lies on. An area without a code or on no patch,
// and a code on more than one area, are errors.
AreasByCode glue_areas_by_code(Verification& v)
{
    AreasByCode by_code;
    for (size_t k = 0; k < v.pieces.size(); ++k) {
        const PieceCheck& piece = v.pieces[k];
        if (!piece.drawn)
            continue;
        for (const DrawnGlue& g : piece.drawn->glue) {
            const int face = piece.drawn->face_at(interior_point({g.polygon, {}}));
            DrawnArea area{k, face >= 0 ? piece.patch_of_face(face) : -1, &g};
            if (g.code.empty()) {
                v.error(DiagnosticCode::tab_unmatched, piece.id + ": the glue area at " +
                                                           at(g.polygon.front()) +
                                                           " carries no code");
                continue;
            }
            if (area.patch < 0) {
                v.error(DiagnosticCode::tab_unmatched,
                        piece.id + ": glue area " + g.code + " lies on no patch of the piece");
                continue;
            }
            by_code[g.code].push_back(area);
        }
    }
    for (const auto& [code, areas] : by_code)
        if (areas.size() > 1)
            v.error(DiagnosticCode::tab_unmatched,
                    "glue code " + code + " is on " + std::to_string(areas.size()) + " glue areas");
    return by_code;
}

// The code on a tab: a text on the tab's face that some glue area carries.
std::string tab_code_on(const DrawnPiece& d, int tab_face, const AreasByCode& by_code)
{
    std::string code;
    for (const DrawnText& t : d.texts)
        if (inside_region(d.faces[size_t(tab_face)], t.position) &&
            (code.empty() || by_code.count(t.text)))
            code = t.text;
    return code;
}

// The design's tab joint on this patch along the crease. Joints can share a line
// (a patch between two others): the one the code glues to, else one not yet taken.
// `gap`: how far the crease is drawn from it. -1 when the design joins the patch to no piece.
int tab_joint(const Verification& v, const PieceCheck& piece, int patch, const DrawnFold& crease,
              int glued_to, double& gap)
{
    const Scaffold& s = v.design;
    const Motion2& m = piece.placed.motion;
    std::vector<std::pair<double, int>> joints;
    for (const Hinge& h : s.hinges) {
        if (h.kind != JointKind::tab || (h.patch_a != patch && h.patch_b != patch))
            continue;
        const std::array<Vec2, 2> line{m(piece.local.flat_point(s, patch, h.from)),
                                       m(piece.local.flat_point(s, patch, h.to))};
        joints.push_back({segment_gap({crease.from, crease.to}, line[0], line[1]), h.id});
    }
    std::sort(joints.begin(), joints.end());
    int joint = -1, free = -1, glued = -1;
    gap = joints.empty() ? 0.0 : joints.front().first;
    for (const auto& [g, id] : joints) {
        if (g > gap + v.tolerance)
            break;
        const Hinge& h = v.hinge(id);
        const int partner = h.patch_a == patch ? h.patch_b : h.patch_a;
        const bool taken = std::any_of(v.tabs.begin(), v.tabs.end(),
                                       [&](const DrawnTab& t) { return t.hinge == id; });
        joint = joint < 0 ? id : joint;
        free = free < 0 && !taken ? id : free;
        glued = glued < 0 && partner == glued_to ? id : glued;
    }
    return glued >= 0 ? glued : free >= 0 ? free : joint;
}

// Which way the tab crease of joint h (the tab on `patch`, glued onto `partner`) must be drawn.
FoldDirection tab_crease_direction(const Verification& v, const PieceCheck& piece, const Hinge& h,
                                   int patch, int partner, const DrawnArea* glue_area)
{
    const Scaffold& s = v.design;
    Hinge seen_from_tab = h;
    seen_from_tab.patch_a = patch;
    seen_from_tab.patch_b = partner;
    bool unspecified = false;
    FoldDirection expected = drawn_direction(s, v.bends, seen_from_tab,
                                             piece.local.printed_normal(s, patch), unspecified);
    if (glue_area && glue_area->patch == partner) {
        // The tab folds onto the side of the joint its glue area is drawn on (a joint
        // inside the partner's paper has room on both sides).
        const DrawnArea& area = *glue_area;
        const PieceCheck& under = v.pieces[area.piece];
        const Motion2& drawing = under.placed.motion;
        const Vec2 glue_point = drawing.rotation.transpose() *
                                (interior_point({area.glue->polygon, {}}) - drawing.translation);
        bool bent = false;
        expected = tab_direction(s, v.bends, h, piece.local, patch, under.local, partner,
                                 glue_point, bent);
    }
    return expected;
}

// A drawn line of piece k that is no design fold: the crease of a tab, checked against the
// design's joint and matched by its code to a glue area (which it then carries), else a line the
// design does not have.
void check_tab_crease(Verification& v, size_t k, size_t f, const AreasByCode& by_code,
                      std::set<std::string>& carried)
{
    const Scaffold& s = v.design;
    PieceCheck& piece = v.pieces[k];
    const DrawnPiece& d = *piece.drawn;
    const auto [patch, tab_face] = tab_crease(
        d, d.folds[f], [&](int face) { return face >= 0 ? piece.patch_of_face(face) : -1; });
    if (tab_face < 0) {
        const DrawnFold& line = d.folds[f];
        v.error(DiagnosticCode::fold_extra,
                piece.id + ": the " + layer(line.direction) + " line from " + at(line.from) +
                    " to " + at(line.to) + " is no fold or tab crease of the design",
                piece.local.flat.patches);
        return;
    }
    const std::string code = tab_code_on(d, tab_face, by_code);
    const auto areas = by_code.find(code);
    const int glued_to = areas == by_code.end() ? -1 : areas->second.front().patch;
    double gap = 0.0;
    const int joint = tab_joint(v, piece, patch, d.folds[f], glued_to, gap);
    if (joint < 0) {
        v.error(DiagnosticCode::fold_extra,
                piece.id + ": a tab hangs from patch " + patch_name(s, patch) +
                    ", which the design joins to no other piece",
                {patch});
        return;
    }
    piece.folds_used.insert(int(f));
    const Hinge& h = v.hinge(joint);
    const int partner = h.patch_a == patch ? h.patch_b : h.patch_a;
    if (gap > v.tolerance)
        v.error(DiagnosticCode::fold_misplaced,
                piece.id + ": the tab crease on patch " + patch_name(s, patch) + " (hinge " +
                    std::to_string(h.id) + ") is drawn " + millimetres(gap) +
                    " off the design's joint",
                {patch, partner});
    const FoldDirection expected = tab_crease_direction(
        v, piece, h, patch, partner, areas == by_code.end() ? nullptr : &areas->second.front());
    if (d.folds[f].direction != expected)
        v.error(DiagnosticCode::fold_direction_wrong,
                piece.id + ": the tab crease on patch " + patch_name(s, patch) + " (hinge " +
                    std::to_string(h.id) + ") is on the " + layer(d.folds[f].direction) +
                    " layer; the tab folds " +
                    (expected == FoldDirection::mountain ? "a mountain" : "a valley") +
                    " seen from the printed side",
                {patch, partner});
    DrawnTab tab{k, patch, joint, int(f), code};
    const std::string name = piece.id + ": tab " + (code.empty() ? "(no code)" : code) +
                             " on patch " + patch_name(s, patch);
    if (areas == by_code.end()) {
        v.error(DiagnosticCode::tab_unmatched,
                name + (code.empty() ? " carries no code" : " has no glue area carrying its code"),
                {patch, partner});
        v.structural = true;
        return;
    }
    carried.insert(code);
    const DrawnArea& area = areas->second.front();
    v.areas[code] = area;
    if (area.patch != partner)
        v.error(DiagnosticCode::tab_wrong_target,
                name + " is glued by its code onto patch " + patch_name(s, area.patch) + " of " +
                    v.pieces[area.piece].id + "; the design joins it to patch " +
                    patch_name(s, partner) + " of " +
                    (v.piece_of(partner) >= 0 ? v.pieces[size_t(v.piece_of(partner))].id : "?") +
                    // A piece that fits its drawing turned round as well cannot tell
                    // which of its tabs carries the wrong code.
                    (piece.candidates.size() > 1
                         ? " (" + piece.id +
                               " fits its outline turned round too: the wrong code may be "
                               "on another of its tabs)"
                         : std::string()),
                {patch, partner, area.patch});
    v.tabs.push_back(tab);
}

// Every glue area needs a tab carrying its code.
void check_areas_carried(Verification& v, const AreasByCode& by_code,
                         const std::set<std::string>& carried)
{
    const Scaffold& s = v.design;
    for (const auto& [code, areas] : by_code)
        if (!carried.count(code)) {
            const DrawnArea& a = areas.front();
            v.error(DiagnosticCode::tab_unmatched,
                    v.pieces[a.piece].id + ": glue area " + code + " on patch " +
                        patch_name(s, a.patch) + " has no tab carrying its code",
                    {a.patch});
        }
}

// Every joint between pieces needs its tab.
void check_joints_have_tabs(Verification& v)
{
    const Scaffold& s = v.design;
    for (const Hinge& h : s.hinges) {
        if (h.kind != JointKind::tab)
            continue;
        const int pa = v.piece_of(h.patch_a), pb = v.piece_of(h.patch_b);
        if (pa == pb || pa < 0 || pb < 0 || !v.pieces[size_t(pa)].drawn ||
            !v.pieces[size_t(pb)].drawn)
            continue;
        // One tab holds every joint along its crease on its patch (a panel standing on the
        // central fold is joined to both pages along one edge); so does one glue area. The
        // crease may lie within the joint (a tab held back from its ends) or the joint within
        // the crease (an outline cut the other patch's edge short; glue_tabs' already_tabbed).
        auto along = [&](int patch, const Vec2& from, const Vec2& to) {
            if (patch != h.patch_a && patch != h.patch_b)
                return false;
            const PieceCheck& on = v.pieces[size_t(v.piece_of(patch))];
            const std::array<Vec2, 2> line{on.placed.motion(on.local.flat_point(s, patch, h.from)),
                                           on.placed.motion(on.local.flat_point(s, patch, h.to))};
            return segment_gap({from, to}, line[0], line[1]) <= v.tolerance + v.tie ||
                   segment_gap(line, from, to) <= v.tolerance + v.tie;
        };
        const bool held =
            std::any_of(v.tabs.begin(), v.tabs.end(),
                        [&](const DrawnTab& t) {
                            const DrawnFold& c = v.pieces[t.piece].drawn->folds[size_t(t.crease)];
                            return t.hinge == h.id || along(t.patch, c.from, c.to);
                        }) ||
            std::any_of(v.areas.begin(), v.areas.end(), [&](const auto& a) {
                return along(a.second.patch, a.second.glue->polygon[0], a.second.glue->polygon[1]);
            });
        if (!held) {
            v.error(DiagnosticCode::joint_without_tab,
                    "the joint of patch " + patch_name(s, h.patch_a) + " on " +
                        v.pieces[size_t(pa)].id + " and patch " + patch_name(s, h.patch_b) +
                        " on " + v.pieces[size_t(pb)].id + " (hinge " + std::to_string(h.id) +
                        ") has no glue tab on the sheets",
                    {h.patch_a, h.patch_b});
            v.structural = true;
        }
    }
}

} // namespace

void check_glue(Verification& v)
{
    const AreasByCode by_code = glue_areas_by_code(v);
    std::set<std::string> carried;
    for (size_t k = 0; k < v.pieces.size(); ++k) {
        const PieceCheck& piece = v.pieces[k];
        if (!piece.drawn)
            continue;
        for (size_t f = 0; f < piece.drawn->folds.size(); ++f)
            if (!piece.folds_used.count(int(f)))
                check_tab_crease(v, k, f, by_code, carried);
    }
    check_areas_carried(v, by_code, carried);
    check_joints_have_tabs(v);
}

} // namespace popup::sheets
