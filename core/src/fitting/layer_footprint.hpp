#pragma once
// Internal: a depth layer's silhouette in its host pair's coordinates (its footprint), and a
// part of the nested mechanism cut to it (fit_depth_layers).
#include <optional>
#include <string>
#include <vector>

#include "popup/fitting/silhouette.hpp"
#include "popup/mechanisms/designed_card.hpp"
#include "popup/model/base_patch_pair.hpp"
#include "popup/model/profile.hpp"
#include "popup/model/result.hpp"
#include "popup/model/scaffold.hpp"

namespace popup::layer_footprint {

/// The patch of `s` named `name`, or null.
const Patch* patch_named(const Scaffold& s, const std::string& name);

/// A layer's silhouette in a host pair's own coordinates: (along the hinge, across it), where
/// "across" runs along `across` (a world direction in the face's plane). Clipped to the room
/// the pair offers: [0, length] along, [lo, hi] across. Loops in that 2-D frame, largest first.
struct Footprint {
    std::vector<Loop2> outer; ///< pieces, each counter-clockwise
    std::vector<std::vector<Loop2>> holes;
    double area = 0.0;                         ///< of the largest piece, holes removed
    Vec2 lo = Vec2::Zero(), hi = Vec2::Zero(); ///< bounds of the largest piece
};

/// The largest piece of `sil` (in the face's profile frame) in the pair's coordinates, clipped
/// to [0, length] along the hinge and [lo, hi] along `across`; none when nothing is left.
std::optional<Footprint> footprint(const Silhouette& sil, const ProfileFrame& face,
                                   const BasePatchPair& pair, const Vec3& across, double lo,
                                   double hi);

/// Cuts `part` of mechanism `name` in `s` to the footprint; the profile it kept (none when the
/// footprint covers the part), or the refusal.
Result<std::optional<FittedProfile>> cut_part(Scaffold& s, const std::string& name,
                                              const std::string& part, const Footprint& f,
                                              const BasePatchPair& pair, const Vec3& across);

} // namespace popup::layer_footprint
