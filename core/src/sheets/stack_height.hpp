#pragma once
#include <vector>

#include "popup/sheets/sheet_set.hpp"

namespace popup::sheets {

/// Height of the closed card: paper layers (patches and glued tabs) over the thickest point,
/// times the paper thickness. Patches are projected onto the ground at the closed state and the
/// layers counted on a grid. `to_sheet[i]` maps patch i (scaffold order) from the design state onto
/// its sheet (z = 0); `closed` the patch poses at 0°.
double stack_height(const Scaffold& s, const SheetSet& sheets, const std::vector<Pose>& to_sheet,
                    const std::vector<Pose>& closed);

} // namespace popup::sheets
