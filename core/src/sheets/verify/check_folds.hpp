#pragma once
// Phase 3 of verify_sheets, the fold lines: each design fold's line, place and layer.
#include "verification.hpp"

namespace popup::sheets {

/// Every design fold of the piece against its drawn line (the one between its two patches'
/// faces, else the nearest): missing is a structural finding, off the crease or on the wrong
/// layer an error. Fills the piece's hinge → drawn fold map and which folds are drawn turned.
void check_folds(Verification& v, PieceCheck& piece);

} // namespace popup::sheets
