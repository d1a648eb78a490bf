#pragma once
#include <vector>

#include "popup/model/result.hpp"
#include "popup/model/scaffold.hpp"
#include "popup/sheets/sheet_drawing.hpp"
#include "popup/sheets/verify_options.hpp"

namespace popup {

/// Proves cutting files against their design using only what the files hold. The CUT loops,
/// moved in by half the kerf, give each piece; its piece label (P1, …) names it. The fold lines
/// split it into faces; each face is matched to a design patch by laying the design's unfolded
/// piece onto the drawing (a rigid motion; a piece printed on its back is turned over). Each fold
/// is folded the way its layer says by the design's angle; each later piece is brought onto the
/// glue area whose code its tab carries. The re-made card is driven through the simulator and
/// every patch compared with the design's over the sweep.
///
/// Result::ok is false for input that cannot be verified at all (a design that does not
/// validate, no drawing, bad options). Otherwise the value says whether every patch lands within
/// 1e-6 × card size; diagnostics name the piece, fold, tab or glue area that is wrong and by how
/// much.
Result<RoundTrip> verify_sheets(const Scaffold& design, const std::vector<SheetDrawing>& drawings,
                                const VerifyOptions& options = {});

} // namespace popup
