#pragma once
// Phase 2 of verify_sheets: each design piece found on the drawing and laid onto it.
#include <vector>

#include "verification.hpp"

namespace popup::sheets {

/// Finds each design piece's drawn piece by its label and the ways the design piece lies on it
/// (register_piece), then chooses one way for each (choose_registrations). A drawn label that
/// names no piece, a piece on no sheet or one whose faces fit no patch are structural findings.
void match_pieces(Verification& v, const std::vector<DrawnPiece>& drawn);

} // namespace popup::sheets
