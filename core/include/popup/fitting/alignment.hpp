#pragma once
#include <optional>
#include <vector>

#include "popup/fitting/supporting_plate.hpp"
#include "popup/fitting/surface_samples.hpp"
#include "popup/input/model_mesh.hpp"
#include "popup/model/card.hpp"
#include "popup/model/result.hpp"

namespace popup {

/// Where the model goes on the card (thesis §5.1.1): which model directions become the card's
/// axes, where its symmetry plane is, and the uniform scale that fits it on the card.
struct Alignment {
    Eigen::Matrix4d model_to_card = Eigen::Matrix4d::Identity(); ///< model units to card mm
    Vec3 up = Vec3::UnitZ();      ///< model direction that became card z (unit)
    Vec3 facing = Vec3::UnitX();  ///< model direction that became card x, toward the viewer
    double scale = 1.0;           ///< card mm per model unit
    double symmetry_error = 0.0;  ///< mean distance of the mirrored samples to the model,
                                  ///< divided by its diagonal (0: mirror-symmetric)
    Eigen::AlignedBox3d card_box; ///< the model's tight bounding box in the card's frame (mm)
    /// The plate the model stands on, when it has one: its top is the card's page, and the box
    /// and scale are those of what stands on it.
    std::optional<SupportingPlate> plate;
};

/// What the card offers the model: its width along the fold and each page's depth, less the
/// free border.
struct CardRoom {
    CardParams card;
    double margin = 0.1; ///< fraction of each card dimension kept free on every side
};

/// The alignments worth fitting, best guess first (docs/MATH.md, "Which way is up"). Up is
/// `up`, else the signed NPCA axis (of the area-weighted normal covariance) whose bounding-box
/// bottom carries the most flat downward-facing area. Card x is `facing`, else the normal of
/// the mirror plane containing up; the fold lies at the middle of the model's extent across x.
/// When that plane is no mirror plane (mean mirrored-sample distance above one sample spacing:
/// an L), the horizontal NPCA axes are offered as x too, and for each x the fold may also
/// stand on the model's two largest inner walls across x (each at least 5 % of its area).
/// Each candidate carries the tight box and the scale that keeps the model inside the closed
/// card. `samples` are the model's pseudo-vertices in model units. Errors name `up` or
/// `facing` when they are zero, not finite, or parallel to each other.
Result<std::vector<Alignment>> alignment_candidates(const ModelMesh& model,
                                                    const SurfaceSamples& samples,
                                                    const std::optional<Vec3>& up,
                                                    const std::optional<Vec3>& facing,
                                                    const CardRoom& room);

/// The first of alignment_candidates(): up, the mirror plane containing it (its normal becomes
/// card x unless `facing` is given), the fold at the middle of the model across it.
Result<Alignment> align_model(const ModelMesh& model, const SurfaceSamples& samples,
                              const std::optional<Vec3>& up, const std::optional<Vec3>& facing,
                              const CardRoom& room);

/// NPCA: the area-weighted covariance Σ A_i n_i n_iᵀ of the face normals and its eigenvectors,
/// largest eigenvalue first (columns).
Mat3 normal_principal_axes(const ModelMesh& model, Vec3* eigenvalues = nullptr);

} // namespace popup
