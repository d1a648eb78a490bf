#pragma once
#include "popup/fitting/prism_ransac.hpp"
#include "popup/fitting/surface_samples.hpp"

namespace popup {

/// The model's bulk as one box, and how close the samples lie to it.
struct BulkBox {
    Prism prism;              ///< rectangular, on the card's hinge (host 0), centred across it
    double mean_distance = 0; ///< mean distance from the samples to the box or the page (mm)
    double page_distance = 0; ///< mean distance from the samples to the page alone (mm)
};

/// The box standing on `card` (its central fold), centred across the hinge as a box fold is,
/// that the samples lie closest to on average: the mean distance from each sample to the box's
/// surface or the page (the pop-up's paper at the design state) is minimised over its extent
/// along the hinge, its depth and its height (coordinate descent over the samples' quantiles,
/// docs/MATH.md, "The model's bulk"). Every dimension is at least `min_part` (mm) and the box
/// stays on the card. The fallback design when no fitted primitive gives a valid one: a round
/// model (a blob) has no face a RANSAC prism can rest on, yet its bulk is a box.
BulkBox bulk_box(const SurfaceSamples& samples, const PrismHost& card, double min_part);

} // namespace popup
