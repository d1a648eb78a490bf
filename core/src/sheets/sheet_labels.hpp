#pragma once
#include <string>

#include "local_piece.hpp"

namespace popup::sheets {

/// The piece id where the most paper is clear of edges and creases, each tab's code on the tab,
/// each glue area's code in it, and optionally M or V beside every fold (in the piece's frame).
void add_labels(LocalPiece& piece, const std::string& piece_id, bool fold_hints);

/// A text angle (degrees) turned by half a turn when needed so the text never reads upside
/// down: the result lies in (-90, 90].
double upright(double degrees);

} // namespace popup::sheets
