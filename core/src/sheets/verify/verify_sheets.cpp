#include "popup/sheets/verify_sheets.hpp"

// The phases, in order. Each reads and fills the Verification (verification.hpp); a check of
// something new the drawing holds goes beside its kind: the cut loops (outline, holes, slots) in
// check_outline, the fold lines in check_folds, the tabs and glue areas in check_glue.
#include "assemble_pieces.hpp"
#include "check_folds.hpp"
#include "check_glue.hpp"
#include "check_outline.hpp"
#include "drawn_piece.hpp"
#include "match_pieces.hpp"
#include "prepare_design.hpp"
#include "round_trip.hpp"
#include "verification.hpp"

namespace popup {

using namespace sheets;

Result<RoundTrip> verify_sheets(const Scaffold& design, const std::vector<SheetDrawing>& drawings,
                                const VerifyOptions& options)
{
    Result<RoundTrip> r;
    if (options.angles < 2 || options.angles > 361)
        r.fail(DiagnosticCode::bad_option,
               "angles = " + std::to_string(options.angles) + ", must be 2 to 361",
               about_parameter("angles"));
    Result<Scaffold> checked = validate_scaffold(design);
    if (!checked.ok) {
        r.fail_with(checked.diagnostics);
        return r;
    }
    const Scaffold& s = checked.value;
    r.value.tolerance = 1e-6 * s.size();
    // Read: the drawings into pieces, each split into faces by its fold lines.
    Result<std::vector<DrawnPiece>> drawn = read_drawn_pieces(drawings, r.diagnostics);
    if (!drawn.ok) {
        r.ok = false;
        r.diagnostics.insert(r.diagnostics.end(), drawn.diagnostics.begin(),
                             drawn.diagnostics.end());
    }
    if (!r.ok)
        return r;
    Verification v(s, options, r.diagnostics);
    if (!prepare_design(v, r))
        return r;
    // Register: each design piece laid onto its drawn piece.
    match_pieces(v, drawn.value);
    // Check what the drawing holds against the design.
    for (PieceCheck& piece : v.pieces)
        if (piece.drawn) {
            check_outline(v, piece);
            check_folds(v, piece);
        }
    check_glue(v);
    // Assemble the card from the drawing alone and fold it against the design.
    std::map<int, Pose> from_sheet;
    if (!v.structural && assemble_pieces(v, from_sheet))
        r.value = compare_round_trip(v, from_sheet);
    r.value.tolerance = 1e-6 * s.size();
    r.value.ok = r.value.ok && !has_errors(r.diagnostics);
    return r;
}

} // namespace popup
