#pragma once
// Internal: the model's bulk as two parts, a box and a box or a tent roof on its top (docs/MATH.md,
// "The model's bulk"): a bust's shoulders and head, a dog's body and raised head, a house's walls
// and roof, where one box of the bulk reads as neither.
#include <optional>

#include "popup/fitting/bulk_prism.hpp"

namespace popup {

struct BulkStack {
    Prism lower; ///< on the card's hinge (host 0), centred across it
    /// On the lower box's top (host 1, the first host offer_box_pairs adds): a box or a tent
    /// (triangular, its ridge over the hinge), a from the lower box's start, centred across it.
    Prism upper;
    double mean_distance = 0; ///< mean distance from the samples to either box or the page (mm)
};

/// The lower box and the box or tent on its top that the samples lie closest to on average, by
/// the same coordinate descent as bulk_box, from `single` (its result) cut at several heights;
/// every dimension at least `min_part`, the upper part on the lower's top. Empty when no stack
/// is feasible.
std::optional<BulkStack> bulk_stack(const SurfaceSamples& samples, const PrismHost& card,
                                    double min_part, const BulkBox& single);

} // namespace popup
