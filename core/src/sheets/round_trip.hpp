#pragma once
#include <vector>

#include "popup/sheets/sheet_layout.hpp"
#include "popup/simulation/simulate_fold.hpp"

namespace popup::sheets {

/// Re-folds the placed sheets and compares them with the design. Geometry comes from the sheets
/// only (patch outlines, fold lines, tab creases and their glue areas); the design supplies each
/// crease's fold angle, as the maker's folding does. The card's ground patch fixes the frame.
/// Each piece is folded along its creases, each later piece is brought onto the glue area that
/// matches its first tab, and the re-made scaffold is driven through the simulator over the same
/// fold angles as the design (`designed`, its sweep over `angles`). `to_sheet[i]` maps patch i
/// (scaffold order) from the design state onto its sheet (3D, sheet plane z = 0): the design
/// side of the comparison, used for fold angles only.
RoundTrip round_trip(const Scaffold& s, const SheetSet& sheets, const std::vector<Pose>& to_sheet,
                     const Result<FoldSweep>& designed, const std::vector<double>& angles,
                     Diagnostics& diagnostics);

} // namespace popup::sheets
