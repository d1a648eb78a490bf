#pragma once
// Phase 3 of verify_sheets, the cut loops: the piece's outline and each patch's face on it.
#include "verification.hpp"

namespace popup::sheets {

/// The piece's cut outline against the design's, and every patch on a face of its own: fills
/// the piece's sheet poses (design state onto the drawing) and its patch → face map. A patch off
/// the paper or two patches in one face are structural findings.
void check_outline(Verification& v, PieceCheck& piece);

} // namespace popup::sheets
