#include "popup/sheets/sheet_drawing.hpp"

namespace popup {

std::vector<SheetDrawing> draw_sheets(const SheetSet& set)
{
    std::vector<SheetDrawing> drawings(size_t(std::max(set.sheet_count, 0)));
    for (size_t k = 0; k < drawings.size(); ++k) {
        drawings[k].name = "sheet " + std::to_string(k + 1);
        drawings[k].kerf = set.options.kerf;
    }
    for (const SheetPiece& piece : set.pieces) {
        if (piece.sheet < 0 || size_t(piece.sheet) >= drawings.size())
            continue;
        SheetDrawing& d = drawings[size_t(piece.sheet)];
        for (const Region& region : piece.cut) {
            d.cut.push_back(region.outer);
            d.cut.insert(d.cut.end(), region.holes.begin(), region.holes.end());
        }
        for (const FoldLine& f : piece.folds)
            d.folds.push_back({f.from, f.to, f.direction});
        for (const GlueArea& g : piece.glue)
            d.glue.push_back(g.polygon);
        for (const SheetLabel& l : piece.labels)
            d.labels.push_back({l.text, l.position});
    }
    return drawings;
}

} // namespace popup
