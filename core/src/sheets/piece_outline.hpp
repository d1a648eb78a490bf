#pragma once
#include <string>
#include <vector>

#include "local_piece.hpp"

namespace popup::sheets {

/// Openings for the slits cut in the piece's patches: a slot as long as the slit and two paper
/// thicknesses wide, so the patch passing through can slide.
void add_slit_slots(const Scaffold& s, LocalPiece& piece);

/// The piece's cut outline: its patches (less holes and slots) and its tabs merged into closed
/// loops (cut_nominal), and the same moved out by half the kerf, holes in (cut).
void cut_outline(LocalPiece& piece, double kerf);

/// Every slot and hole must stay open once the cut path moves half a kerf into it: an error names
/// each one that closes and the largest kerf that keeps it.
void check_openings_survive_kerf(const LocalPiece& piece, const std::string& piece_id, double kerf,
                                 Diagnostics& diagnostics);

/// Die-cutting warnings: paper narrower than `min_feature` (what a morphological opening of that
/// width removes) and convex corners sharper than `min_corner_angle` degrees.
void check_die_cutting(const LocalPiece& piece, const std::string& piece_id,
                       const SheetOptions& options, Diagnostics& diagnostics);

} // namespace popup::sheets
