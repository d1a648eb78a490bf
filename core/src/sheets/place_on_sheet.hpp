#pragma once
// A stage of layout_sheets: a piece laid flat, moved onto its sheet where the nesting put it.
#include <string>
#include <vector>

#include "local_piece.hpp"

namespace popup::sheets {

/// The piece laid flat moved onto its sheet where the nesting put it (a quarter turn, exact, and
/// a shift): its patches with their frames, cut loops, folds, tabs, glue areas and labels (kept
/// upright). `to_sheet[i]` gets the pose of patch i (scaffold order) from the design state onto
/// the sheet (z = 0).
SheetPiece place_on_sheet(const Scaffold& s, const LocalPiece& local, const Placement& at,
                          const std::string& piece_id, std::vector<Pose>& to_sheet);

} // namespace popup::sheets
