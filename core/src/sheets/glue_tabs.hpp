#pragma once
#include <map>
#include <vector>

#include "fold_directions.hpp"
#include "local_piece.hpp"

namespace popup::sheets {

/// For every tab joint between two pieces, a trapezoidal glue tab on the piece glued later (the
/// carrier), to be folded over onto the other piece's patch, and the matching glue area there.
/// A tab starts `tab_width` deep and narrows until it overlaps nothing: not its own piece, not
/// the piece's other tabs; its glue area must lie on the target patch, clear of other glue
/// areas. No room even at `min_tab_width` is an error. Codes A, B, … follow the assembly order
/// (`pieces` are in assembly order; `position` maps a patch id to its piece).
void add_glue_tabs(const Scaffold& s, std::vector<LocalPiece>& pieces,
                   const std::map<int, int>& position, const BendSamples& bends,
                   const SheetOptions& options, Diagnostics& diagnostics);

/// Tab codes: A … Z, AA, AB, …
std::string tab_code(int index);

} // namespace popup::sheets
