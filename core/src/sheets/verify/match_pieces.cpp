#include "match_pieces.hpp"

#include <algorithm>

#include "../../geometry/clipper_paths.hpp"
#include "../clipper_ops.hpp"
#include "choose_registrations.hpp"

namespace popup::sheets {

namespace {

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

} // namespace

void match_pieces(Verification& v, const std::vector<DrawnPiece>& drawn)
{
    const Scaffold& s = v.design;
    for (const DrawnPiece& d : drawn)
        if (std::none_of(v.pieces.begin(), v.pieces.end(),
                         [&](const PieceCheck& p) { return p.id == d.id; })) {
            v.error(DiagnosticCode::unlabelled_piece,
                    d.drawing + ": " + d.id + " is not a piece of the design (it has P1 to P" +
                        std::to_string(v.pieces.size()) + ")");
            v.structural = true;
        }
    for (PieceCheck& piece : v.pieces) {
        const LocalPiece& local = piece.local;
        for (const DrawnPiece& d : drawn)
            if (d.id == piece.id)
                piece.drawn = &d;
        if (!piece.drawn) {
            v.error(DiagnosticCode::missing_piece, piece.id + " is on no sheet",
                    local.flat.patches);
            v.structural = true;
            continue;
        }
        std::vector<std::array<Vec2, 2>> joints;
        for (const Hinge& h : s.hinges)
            for (int patch : {h.patch_a, h.patch_b})
                if (h.kind == JointKind::tab && local.has(patch))
                    joints.push_back(
                        {local.flat_point(s, patch, h.from), local.flat_point(s, patch, h.to)});
        piece.candidates =
            register_piece(local.flat.outlines, union_of(local), local.flat.fold_lines, joints,
                           *piece.drawn, v.tolerance + v.tie);
        if (piece.candidates.empty()) {
            v.error(DiagnosticCode::outline_mismatch,
                    piece.id + ": none of its faces has the shape of a patch of the design",
                    local.flat.patches);
            v.structural = true;
            piece.drawn = nullptr;
        }
    }
    choose_registrations(v);
}

} // namespace popup::sheets
