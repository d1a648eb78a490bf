#pragma once
// A piece laid flat in its own frame (the root patch's 2D frame), before it is placed on a sheet:
// the shared state the layout steps (tabs, outline, labels, round trip) fill in turn.
#include <map>
#include <vector>

#include "popup/sheets/sheet_set.hpp"
#include "popup/sheets/unfold_piece.hpp"

namespace popup::sheets {

/// The opening cut for one slit.
struct SlitSlot {
    int slit = 0;  ///< the slit's id
    int patch = 0; ///< the patch it is cut in
    Loop2 loop;
};

struct LocalPiece {
    FlatPiece flat;
    std::map<int, int> index_of; ///< patch id → index in flat.patches
    std::vector<FoldLine> folds;
    std::vector<GlueTab> tabs;
    std::vector<GlueArea> glue;
    std::vector<SlitSlot> slots; ///< openings cut for slits
    std::vector<Region> cut_nominal;
    std::vector<Region> cut;
    std::vector<SheetLabel> labels;
    bool printed_back = false; ///< turned over: the root's normal side faces down

    bool has(int patch) const { return index_of.count(patch) > 0; }
    /// A design-state point of one of the piece's patches, in the piece's flat frame.
    Vec2 flat_point(const Scaffold& s, int patch, const Vec3& x) const;
    /// The normal of the piece's printed (upper) side on one of its patches, at the design state.
    Vec3 printed_normal(const Scaffold& s, int patch) const;
    const Loop2& outline(int patch) const { return flat.outlines[index_of.at(patch)]; }
};

/// Lays a piece flat and snaps vertices closer than `tol` onto one point, so that patches which
/// share an edge share its exact coordinates (Clipper merges them in the outline).
Result<LocalPiece> lay_flat(const Scaffold& s, const std::vector<int>& patches, double tol,
                            bool printed_back);

/// The unit normal on the left of a unit direction.
Vec2 left_normal(const Vec2& direction);

} // namespace popup::sheets
