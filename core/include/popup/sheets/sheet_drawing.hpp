#pragma once
#include <string>
#include <vector>

#include "popup/sheets/sheet_set.hpp"

namespace popup {

/// A line on the MOUNTAIN or VALLEY layer.
struct DrawnFold {
    Vec2 from = Vec2::Zero();
    Vec2 to = Vec2::Zero();
    FoldDirection direction = FoldDirection::valley; ///< its layer
};

/// A text on the LABEL layer: a piece id (P1, …), a tab code, a glue code (`A1` or `A1 (back)`),
/// a fold hint or the NOT VALID stamp.
struct DrawnText {
    std::string text;
    Vec2 position = Vec2::Zero(); ///< the text's centre
};

/// What one cutting file holds, and nothing else: the maker's view of a sheet (or of all sheets
/// side by side). Coordinates in mm, printed side up.
struct SheetDrawing {
    std::string name;             ///< the file, for messages
    double kerf = 0.0;            ///< the cut width the CUT loops were offset by (half each side)
    std::vector<Loop2> cut;       ///< CUT loops: outlines and holes, in any orientation
    std::vector<DrawnFold> folds; ///< fold lines and tab creases
    std::vector<Loop2> glue;      ///< glue areas; the first edge is where the tab's crease lands
    std::vector<DrawnText> labels;
};

/// The drawings the writers make of a sheet set: one per sheet, the same entities as the DXF
/// layers (docs/SHEET_FORMAT.md).
std::vector<SheetDrawing> draw_sheets(const SheetSet& sheets);

} // namespace popup
