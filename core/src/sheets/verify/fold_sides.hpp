#pragma once
// Which faces of a drawn piece lie on either side of a drawn line: a fold joins two patches' faces,
// a tab's crease a patch's face and the tab's.
#include <utility>

#include "drawn_piece.hpp"

namespace popup::sheets {

/// The faces on either side of a drawn fold line (-1 where there is no paper).
std::pair<int, int> sides(const DrawnPiece& piece, const DrawnFold& f);

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

} // namespace popup::sheets
