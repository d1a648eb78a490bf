#pragma once
#include "popup/fitting/prism_ransac.hpp"
#include "popup/fitting/surface_samples.hpp"

namespace popup {

/// The box standing on `card` (its central fold), centred across the hinge as a box fold is,
/// that the samples lie closest to on average: the mean distance from each sample to the box's
/// surface or the page (the pop-up's paper at the design state) is minimised over its extent
/// along the hinge, its depth and its height (coordinate descent over the samples' quantiles,
/// docs/MATH.md, "The model's bulk"). Every dimension is at least `min_part` (mm) and the box
/// stays on the card. The fallback design when no fitted primitive gives a valid one: a round
/// model (a blob) has no face a RANSAC prism can rest on, yet its bulk is a box.
Prism bulk_prism(const SurfaceSamples& samples, const PrismHost& card, double min_part);

/// Mean distance from the samples (card frame) to the surface of `box` (rectangular, on the
/// flat host `card`) or to the page z = 0 of the host, whichever is nearer.
double mean_distance_to_box(const SurfaceSamples& samples, const PrismHost& card, const Prism& box);

} // namespace popup
