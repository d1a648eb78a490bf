#pragma once
#include "popup/model/base_patch_pair.hpp"
#include "popup/model/result.hpp"
#include "popup/model/scaffold.hpp"

namespace popup {

/// A folded card: two pages of `depth` on either side of a central fold of length `width`, open
/// flat at the design state (thesis §4.3 frame: fold along y from the origin, ground at x > 0).
struct CardParams {
    double width = 210.0; ///< along the central fold (mm)
    double depth = 148.0; ///< each page, from the fold to its edge (mm)
    double paper_thickness = 0.2;
    std::string name = "Card"; ///< what error messages call the card (its FreeCAD Label)
};

/// The card's scaffold (ground id 0, backdrop id 1, the central fold as hinge 0). Errors name the
/// parameter and its allowed range.
Result<Scaffold> make_card(const CardParams& params);

/// The central fold as a base patch pair.
BasePatchPair central_fold(const Scaffold& card);

} // namespace popup
