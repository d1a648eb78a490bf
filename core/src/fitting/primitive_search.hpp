#pragma once
// Internal: fit_design's primitive stage: the volumetric RANSAC from the central fold under
// every alignment the model offers, and the alignment whose primitives explain it best.
#include <cstddef>
#include <vector>

#include "popup/fitting/alignment.hpp"
#include "popup/fitting/fit_types.hpp"
#include "popup/fitting/prism_ransac.hpp"
#include "popup/fitting/surface_samples.hpp"

namespace popup {

/// The primitive search under one alignment.
struct PrimitiveSearch {
    SurfaceSamples samples; ///< the model's samples placed on the card (mm)
    RansacOptions ro;
    RansacResult fit;
    double explained = 0;      ///< samples on a prism's paper faces or on a host's page
    std::size_t alignment = 0; ///< which of the alignments it ran under
};

/// fit_prisms on `model_samples` (model units) placed by each of `alignments`, with the
/// options' threshold, τ, probability, seed, mechanism count and thinnest part. The alignment
/// whose primitives' paper faces (not their open ends) explain the most samples; the first
/// (the mirror plane) unless another explains a hundredth more (docs/MATH.md, "Which way is
/// up").
PrimitiveSearch search_primitives(const ModelMesh& model, const SurfaceSamples& model_samples,
                                  const std::vector<bool>& inner,
                                  const std::vector<Alignment>& alignments,
                                  const FitOptions& options, const CancelFlag* cancel);

} // namespace popup
