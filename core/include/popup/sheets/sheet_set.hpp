#pragma once
// The data of the sheets pipeline: the options a card is laid out with and the sheet set it
// gives (pieces, their folds, glue tabs and areas, labels, the assembly and the round trip).
// The layout's stages and every writer read these; the driver (sheet_layout.hpp) makes them.
#include <map>
#include <string>
#include <vector>

#include "popup/model/cancel_flag.hpp"
#include "popup/model/result.hpp"
#include "popup/model/scaffold.hpp"
#include "popup/sheets/nest.hpp"

namespace popup {

/// The side of a piece its artwork is printed on, which faces up on the sheet. `front` is the
/// side its first patch's normal points to (the card's inside, where the pop-ups stand); `back`
/// turns the piece over. Folds are mountain or valley, glue areas front or back, as seen from it.
enum class PrintedSide { front, back };
const char* to_string(PrintedSide side);

/// How to lay a card out for cutting. Lengths in mm, angles in degrees.
struct SheetOptions {
    NestOptions nest;               ///< paper, margin, spacing, rotations
    double kerf = 0.1;              ///< cut width; cut lines move out by half of it
    double min_gap = 1.0;           ///< spacing must be at least kerf + min_gap
    double tab_width = 8.0;         ///< glue tab depth, away from its crease
    double tab_angle = 45.0;        ///< angle between the crease and a tab's side, (0, 90]
    double min_tab_width = 3.0;     ///< narrowest tab worth gluing
    double min_feature = 3.0;       ///< die cutting: narrower paper gets a warning
    double min_corner_angle = 30.0; ///< die cutting: sharper convex corners get a warning
    bool fold_hints = false;        ///< print M/V beside each fold
    int round_trip_angles = 13;     ///< fold angles sampled by the round trip, ≥ 2
    std::map<std::string, PrintedSide> printed_sides; ///< by piece id (P1, …); front if absent
    const CancelFlag* cancel = nullptr; ///< set from another thread: the layout throws Cancelled
};

/// Checks every option; errors name the option, its value and the allowed range.
Diagnostics check_sheet_options(const SheetOptions& options);

/// The shortest crease that still carries a glue tab of `options.min_tab_width` (mm): a tab's
/// sides lean in at tab_angle and its far edge keeps a tenth of the crease, so its depth is at
/// most 0.45 · crease · tan(tab_angle); where the paper around is in the way the layout holds
/// the tab back from the crease's ends by up to a fifth of it on each side (3/5 of the crease
/// left). The narrowest tab fits in all those tries from 3 mm / (0.45 · tan 45° · 3/5) ≈ 11.1 mm;
/// shorter joints may get no tab (no_room_for_tab). The glue area needs as much depth on the
/// patch it lands on, hence at least min_tab_width.
double shortest_tabbed_crease(const SheetOptions& options);

struct FlatPatch {
    int id = 0;
    std::string name;
    Loop2 outer;
    std::vector<Loop2> holes;
    /// The patch's own 2D frame (Patch::to_local at the design state) onto the sheet: a point
    /// (u, v) lands at to_sheet.leftCols<2>() * (u, v) + to_sheet.col(2). A rotation when the
    /// patch's normal side faces up (is printed), a reflection when its back side does. Artwork
    /// rendered in the patch frame is placed with it. Zero for a patch read from a sheet set
    /// written before it existed (sheet_set_from_json).
    Eigen::Matrix<double, 2, 3> to_sheet = Eigen::Matrix<double, 2, 3>::Identity();

    /// The normal side faces up on the sheet, the printed side (else the back side does).
    bool normal_side_up() const { return to_sheet.leftCols<2>().determinant() > 0.0; }
    /// False for a patch read from a sheet set that gives no to_sheet for it.
    bool has_to_sheet() const { return !to_sheet.isZero(0.0); }
};

/// A closed outline with holes (a region of one piece).
struct Region {
    Loop2 outer;
    std::vector<Loop2> holes;
};

struct FoldLine {
    int hinge = 0;
    Vec2 from = Vec2::Zero();
    Vec2 to = Vec2::Zero();
    FoldDirection direction = FoldDirection::valley; ///< seen from the printed (upper) side
    JointKind kind = JointKind::fold;                ///< tab: the crease at a glue tab's foot
};

struct GlueTab {
    std::string code;
    int hinge = 0;
    int patch = 0; ///< the patch it hangs from
    Loop2 polygon; ///< first edge = the crease
    double width = 0.0;
    int target_piece = 0;
    int target_patch = 0;
    bool front = true; ///< glued to the target's printed side
};

struct GlueArea {
    std::string code;
    int hinge = 0;
    int patch = 0; ///< the patch it lies on
    Loop2 polygon; ///< first edge = where the tab's crease lands
    int tab_piece = 0;
    bool front = true;
};

struct SheetLabel {
    std::string text;
    std::string kind; ///< piece, tab, glue, fold
    Vec2 position = Vec2::Zero();
    double height = 0.0;
    double angle = 0.0; ///< degrees, counter-clockwise
};

/// One piece of paper placed on its sheet (sheet coordinates, origin at the paper's lower-left
/// corner, printed side up).
struct SheetPiece {
    std::string id; ///< P1, P2, … (P1 is the card)
    PrintedSide printed_side = PrintedSide::front;
    int sheet = 0;
    double rotation = 0.0;
    std::vector<FlatPatch> patches;
    std::vector<Region> cut;         ///< kerf-compensated outline, tabs merged in
    std::vector<Region> cut_nominal; ///< the same without kerf
    std::vector<FoldLine> folds;
    std::vector<GlueTab> tabs;
    std::vector<GlueArea> glue;
    std::vector<SheetLabel> labels;
};

struct AssemblyJoin {
    std::string code;
    int tab_piece = 0;
    int target_piece = 0;
    bool front = true;
};

struct AssemblyStep {
    int piece = 0; ///< index into SheetSet::pieces
    std::vector<AssemblyJoin> joins;
    std::string text;
};

/// The flat pieces re-folded through the simulator and compared with the design.
struct RoundTrip {
    double max_error = 0.0; ///< largest patch-vertex distance over the sampled angles (mm)
    double tolerance = 0.0; ///< 1e-6 × card size
    int angles = 0;
    bool ok = false;
};

struct SheetSet {
    SheetOptions options;
    double card_size = 0.0;       ///< the design's size (Scaffold::size), the tolerance scale
    double paper_thickness = 0.0; ///< the design's (mm)
    int sheet_count = 0;
    int shelf_sheet_count = 0;      ///< the bounding-box shelf packer's count, the baseline
    std::vector<SheetPiece> pieces; ///< the card first
    std::vector<AssemblyStep> assembly;
    double cut_length = 0.0;   ///< total length of the kerf-compensated cut loops
    double stack_height = 0.0; ///< closed card: paper layers × thickness at the thickest point
    RoundTrip round_trip;
    Diagnostics diagnostics; ///< errors: the sheets cannot be used as they are
};

} // namespace popup
