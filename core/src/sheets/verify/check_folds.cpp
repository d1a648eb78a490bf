#include "check_folds.hpp"

#include <algorithm>

#include "../../model/millimetres.hpp"
#include "fold_sides.hpp"

namespace popup::sheets {

void check_folds(Verification& v, PieceCheck& piece)
{
    const Scaffold& s = v.design;
    const LocalPiece& local = piece.local;
    const DrawnPiece& d = *piece.drawn;
    const Motion2& m = piece.placed.motion;
    for (size_t i = 0; i < local.flat.folds.size(); ++i) {
        const Hinge& h = v.hinge(local.flat.folds[i]);
        const std::array<Vec2, 2> line{m(local.flat.fold_lines[i][0]),
                                       m(local.flat.fold_lines[i][1])};
        const std::string what = piece.id + ": the fold between patches " +
                                 patch_name(s, h.patch_a) + " and " + patch_name(s, h.patch_b) +
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
            v.error(DiagnosticCode::fold_missing, what + " has no fold line",
                    {h.patch_a, h.patch_b});
            v.structural = true;
            continue;
        }
        piece.fold_of[h.id] = best;
        piece.folds_used.insert(best);
        if (gap > v.tolerance)
            v.error(DiagnosticCode::fold_misplaced,
                    what + " is drawn " + millimetres(gap) + " off the design's crease",
                    {h.patch_a, h.patch_b});
        bool unspecified = false;
        const FoldDirection expected =
            drawn_direction(s, v.bends, h, local.printed_normal(s, h.patch_a), unspecified);
        const FoldDirection drawn = d.folds[size_t(best)].direction;
        piece.fold_turned[h.id] = drawn != expected;
        if (drawn != expected)
            v.error(DiagnosticCode::fold_direction_wrong,
                    what + " is on the " + layer(drawn) + " layer; the design folds it " +
                        (expected == FoldDirection::mountain ? "a mountain" : "a valley") +
                        " seen from the printed side",
                    {h.patch_a, h.patch_b});
    }
}

} // namespace popup::sheets
