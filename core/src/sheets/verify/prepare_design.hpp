#pragma once
// Phase 1 of verify_sheets: the design's side, laid flat and swept, before any drawing is read.
#include "verification.hpp"

namespace popup::sheets {

/// Lays every piece of the design flat, in assembly order and turned over where the sheets were
/// printed on its back, and simulates the design over the angles to check (the asked ones and
/// the fold-direction samples). False, with `r` failed, when a printed side names no piece, a
/// piece cannot be laid flat or the design does not simulate.
bool prepare_design(Verification& v, Result<RoundTrip>& r);

} // namespace popup::sheets
