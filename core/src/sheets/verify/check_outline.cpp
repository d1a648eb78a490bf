#include "check_outline.hpp"

#include "../../model/millimetres.hpp"

namespace popup::sheets {

void check_outline(Verification& v, PieceCheck& piece)
{
    const Scaffold& s = v.design;
    const LocalPiece& local = piece.local;
    const DrawnPiece& d = *piece.drawn;
    if (piece.placed.outline_error > v.tolerance)
        v.error(DiagnosticCode::outline_mismatch,
                piece.id + ": its cut outline is " + millimetres(piece.placed.outline_error) +
                    " off the design's (farthest at " + at(piece.placed.outline_worst) + " on " +
                    d.drawing + ")",
                local.flat.patches);
    // Design state → the root's plane → its 2D frame (turned over for a back print) → drawing.
    const Patch& root = *s.find_patch(local.flat.patches.front());
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
            v.error(DiagnosticCode::outline_mismatch,
                    piece.id + ": patch " + patch_name(s, id) + " is not on the cut piece (" +
                        at(inside) + " on " + d.drawing + " is off the paper)",
                    {id});
            v.structural = true;
            continue;
        }
        if (const int other = piece.patch_of_face(face); other >= 0) {
            v.error(DiagnosticCode::fold_not_separating,
                    piece.id + ": patches " + patch_name(s, other) + " and " + patch_name(s, id) +
                        " lie in one face: no fold line cuts between them",
                    {other, id});
            v.structural = true;
            continue;
        }
        piece.face_of[id] = face;
    }
}

} // namespace popup::sheets
