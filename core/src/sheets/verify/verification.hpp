#pragma once
// What verify_sheets knows as it goes: the design laid flat piece by piece, how each piece lies
// on the drawing, which drawn line is which fold or tab crease, and the findings so far. The
// phases (prepare_design, match_pieces, check_outline, check_folds, check_glue, assemble_pieces,
// compare_round_trip) each read it and fill in their part.
#include <map>
#include <set>
#include <string>
#include <vector>

#include "../fold_directions.hpp"
#include "../local_piece.hpp"
#include "drawn_piece.hpp"
#include "popup/sheets/verify_options.hpp"
#include "popup/simulation/simulate_fold.hpp"
#include "register_piece.hpp"

namespace popup::sheets {

// One piece of the design and what the drawing makes of it.
struct PieceCheck {
    std::string id;
    LocalPiece local;
    const DrawnPiece* drawn = nullptr;
    std::vector<Registration> candidates; // the ways it fits the drawing equally well
    Registration placed;                  // the one chosen
    std::map<int, int> face_of;           // patch id → drawn face
    std::map<int, Pose> sheet_pose;       // patch id → design state onto the drawing (z = 0)
    std::map<int, int> fold_of;           // fold hinge id → drawn fold
    std::map<int, bool> fold_turned;      // fold hinge id → drawn the other way than designed
    std::set<int> folds_used;             // drawn folds that are a fold or a tab crease

    int patch_of_face(int face) const
    {
        for (const auto& [patch, f] : face_of)
            if (f == face)
                return patch;
        return -1;
    }
};

struct DrawnTab {
    size_t piece = 0; // PieceCheck index
    int patch = 0;    // the patch it hangs from
    int hinge = -1;   // the design's tab joint it makes
    int crease = 0;   // drawn fold index on its piece
    std::string code;
};

struct DrawnArea {
    size_t piece = 0;
    int patch = -1;
    const DrawnGlue* glue = nullptr;
};

/// The design, the options and everything the phases have found out so far.
struct Verification {
    Verification(const Scaffold& design, const VerifyOptions& options, Diagnostics& findings);

    const Scaffold& design;
    const VerifyOptions& options;
    Diagnostics& findings;
    double tolerance;
    double tie = 1e-3;          // mm: registrations this close in fit are the same fit
    std::vector<double> angles; // the angles asked for and the fold-direction samples
    std::vector<double> asked;
    Result<FoldSweep> designed;
    BendSamples bends;
    std::vector<PieceCheck> pieces;
    std::vector<DrawnTab> tabs;
    std::map<std::string, DrawnArea> areas; // by code: the glue area a tab goes onto
    bool structural = false;                // the drawing cannot be rebuilt into the design's card

    void error(DiagnosticCode code, const std::string& message, std::vector<int> patches = {});
    const Hinge& hinge(int id) const;
    int piece_of(int patch) const;
    /// Hinge h's line runs through the inside of `patch` (its paper lies on both sides of it).
    bool joint_inside(int patch, const Hinge& h) const;
};

// In messages.
std::string at(const Vec2& p);
const char* layer(FoldDirection d);
std::string patch_name(const Scaffold& s, int id);

/// A point of the sheet's plane in 3D (z = 0).
inline Vec3 lift(const Vec2& p)
{
    return {p.x(), p.y(), 0.0};
}

} // namespace popup::sheets
