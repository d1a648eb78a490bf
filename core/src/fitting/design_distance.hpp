#pragma once
// Internal: how near the model's samples lie to a design's patches (fit_design's coverage, and
// its judge between the fitted design and the bulk box).
#include "popup/fitting/surface_samples.hpp"
#include "popup/model/scaffold.hpp"

namespace popup {

/// The fraction of the samples within `eps` of a patch of `scaffold`.
double coverage_of(const Scaffold& scaffold, const SurfaceSamples& samples, double eps);

/// Mean distance from (at most 3000 of) the samples to the scaffold's patches.
double mean_distance_to(const Scaffold& scaffold, const SurfaceSamples& samples);

} // namespace popup
