#pragma once
#include <array>
#include <vector>

#include "popup/model/result.hpp"
#include "popup/model/scaffold.hpp"

namespace popup {

/// A piece of paper laid flat: every patch keeps its exact shape (a rigid motion of its design
/// outline), patches joined by the piece's folds share those folds, and the root patch keeps its
/// own 2D frame (Patch::to_local). Lengths in mm.
struct FlatPiece {
    std::vector<int> patches;                    ///< patch ids, root first, in unfolding order
    std::vector<Loop2> outlines;                 ///< outer loop of each, in the sheet plane
    std::vector<std::vector<Loop2>> holes;       ///< holes of each
    std::vector<int> folds;                      ///< ids of the hinges inside the piece
    std::vector<std::array<Vec2, 2>> fold_lines; ///< each fold's segment in the sheet plane
    std::vector<Pose> unfold; ///< per patch: design state → the root's plane (3D), for checks
};

/// Unfolds the patches `piece` (ids; the first is the root) joined by the folds among them (tab
/// joints are where pieces meet, not creases):
/// each patch turns about its fold with its parent until it lies flat beside it, on the far side
/// of the fold (a spanning tree from the root). A fold that closes a loop must land where the
/// tree put it, else the piece cannot be flattened without stretching: an error names it.
Result<FlatPiece> unfold_piece(const Scaffold& scaffold, const std::vector<int>& piece);

} // namespace popup
