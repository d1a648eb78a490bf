#pragma once
// A cutting file read back as pieces: what `verify_sheets` rebuilds, from the drawing alone.
#include <string>
#include <vector>

#include "popup/sheets/sheet_drawing.hpp"

namespace popup::sheets {

/// A glue area on a piece and the code printed in it.
struct DrawnGlue {
    Loop2 polygon; ///< first edge = where the tab's crease lands
    std::string code;
    bool back = false; ///< labelled "<code> (back)": the tab goes on the other face
};

/// One connected piece of paper as the file draws it, at its nominal size (the CUT loops moved
/// in by half the kerf), split into faces by its fold lines.
struct DrawnPiece {
    std::string id;      ///< its piece label (P1, …)
    std::string drawing; ///< the file it is in
    Region outline;
    std::vector<DrawnFold> folds; ///< fold lines and tab creases on it
    std::vector<Region> faces;    ///< the outline cut along every fold line
    std::vector<DrawnGlue> glue;
    std::vector<DrawnText> texts; ///< other labels on it (tab codes, hints), not in a glue area

    /// Index of the face holding q, or -1.
    int face_at(const Vec2& q) const;
};

/// Reads every drawing into pieces. Drawings that cannot be read at all (no CUT loop, a loop of
/// fewer than three points, a coordinate that is not finite) fail; a cut region without exactly
/// one piece label, or a label on two regions, is a finding and the region is left out.
Result<std::vector<DrawnPiece>> read_drawn_pieces(const std::vector<SheetDrawing>& drawings,
                                                  Diagnostics& findings);

/// A point well inside the region (off its boundary, out of its holes).
Vec2 interior_point(const Region& region);

bool inside_region(const Region& region, const Vec2& q);

} // namespace popup::sheets
