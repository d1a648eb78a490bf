#pragma once
#include <string>
#include <vector>

#include "popup/model/profile.hpp"

namespace popup {

/// What apply_profile did.
struct ProfileApplied {
    int patch = -1;
    ProfileFrame frame;
    double area_before = 0.0; ///< mm²
    double area_after = 0.0;  ///< mm²
    std::vector<int> hinges;  ///< ids of the patch's hinges after clipping (new ids for splits)
    int dropped_pieces = 0;   ///< pieces of paper the profile cut off every fold (dropped)
    Diagnostics warnings;     ///< what the result's warnings say, kept with the value
};

/// Cuts a patch to a profile: the patch's outline becomes its current outline (what its
/// mechanism generated) ∩ the profile, an exact boolean on Clipper's nanometre grid. Each hinge
/// and slit of the patch is clipped to the paper left along it, so the fold shrinks for the
/// neighbouring patch too; a hinge crossing several stretches of paper becomes several hinges
/// (the first keeps its id). Pieces of the result that hold none of the patch's folds are
/// dropped (a warning says how many); two or more pieces that each hold a fold are refused.
///
/// Errors, with the scaffold left unchanged: unknown_patch, bad_profile (bad loops, nothing
/// left of the patch, several pieces holding folds), profile_misses_hinge (a fold or slit keeps
/// less than shortest_fold of paper; names the patch, the fold and the profile).
Result<ProfileApplied> apply_profile(Scaffold& scaffold, int patch_id, const Profile& profile);

/// The same for the patch named "<mechanism>.<part>" (e.g. "B1" and "FL", "Step" and "riser").
Result<ProfileApplied> apply_profile(Scaffold& scaffold, const std::string& mechanism,
                                     const std::string& part, const Profile& profile);

} // namespace popup
