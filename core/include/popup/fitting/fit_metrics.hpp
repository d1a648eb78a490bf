#pragma once
#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "popup/input/model_mesh.hpp"
#include "popup/model/result.hpp"
#include "popup/model/scaffold.hpp"

namespace popup {

/// Distances from the points of one surface to another (mm or relative).
struct DistanceStats {
    double mean = 0.0; ///< area-weighted mean over uniform surface samples
    double rms = 0.0;  ///< root mean square over the same samples
    double max = 0.0;  ///< one-sided Hausdorff distance (CGAL bounded-error)
};

struct FitMetricsOptions {
    double threshold_mm = 1.0;     ///< coverage counts model samples this close to the pop-up
    int samples = 20000;           ///< uniform surface samples per direction
    std::uint64_t seed = 1;        ///< seeds the samples
    double hausdorff_error = 1e-3; ///< Hausdorff error bound, a fraction of the diagonal
    int volume_cells = 64;         ///< grid cells along the longest side, for the volume difference
};

/// How well a pop-up at its design state (the card open flat) matches its model, in the card's
/// frame (docs/MATH.md, "Fit metrics"). Relative values are divided by `diagonal_mm`.
struct FitMetrics {
    double diagonal_mm = 0.0; ///< the model's bounding-box diagonal in card mm
    DistanceStats model_to_popup_mm, popup_to_model_mm;
    DistanceStats model_to_popup, popup_to_model; ///< the same divided by diagonal_mm
    bool model_closed = false; ///< the model bounds a volume (else no volume figures)
    static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    double model_volume_mm3 = nan;  ///< exact, by the divergence theorem
    double popup_volume_mm3 = 0.0;  ///< the union of the prisms, on the grid
    double volume_difference = nan; ///< |model xor prisms| / |model|, both on the grid
    double coverage = 0.0;          ///< fraction of model samples within threshold_mm of the pop-up
};

/// Measures `model` (model units, taken to card mm by `model_to_card`, an affine 4x4) against
/// `design` posed at 180° (its patches triangulated with their holes) and against the union of
/// `prisms` (each the corners of a convex prism in card mm). The model is compared with every
/// patch; the pop-up side leaves out the two base patches, the card under the shape.
/// Errors (bad_option) name the bad option, matrix entry or prism; a model check_model refuses.
Result<FitMetrics> fit_metrics(const ModelMesh& model, const Eigen::Matrix4d& model_to_card,
                               const Scaffold& design, const std::vector<std::vector<Vec3>>& prisms,
                               const FitMetricsOptions& options = {});

} // namespace popup
