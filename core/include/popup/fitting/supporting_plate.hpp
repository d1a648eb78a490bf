#pragma once
// A ground plate, terrain slab, pedestal or print bed under a model: the card's page, not a part
// of the pop-up (docs/MATH.md, "The plate under a model").
#include <optional>

#include "popup/fitting/surface_samples.hpp"
#include "popup/input/model_mesh.hpp"

namespace popup {

/// The plate a model stands on: the level of its top along `up` (model units).
struct SupportingPlate {
    Vec3 up = Vec3::UnitZ(); ///< unit, the model's up
    double top = 0.0;        ///< up · p of the plate's top face
    double thickness = 0.0;  ///< from the model's bottom to the plate's top
    double top_area = 0.0;   ///< flat upward-facing area at the top level (model units²)
};

/// The plate under the model along `up`, if it has one: a flat upward-facing level in the lowest
/// quarter of the model's height, at most a quarter of it thick, whose flat area is at least a
/// third of the model's footprint, while what stands above it covers at most 70 % of that
/// footprint and rises at least twice the plate's thickness. A model that is only a plate has
/// nothing above it and no plate.
std::optional<SupportingPlate> supporting_plate(const ModelMesh& model, const Vec3& up);

/// The model without the plate: the triangles lying wholly at or below its top (within a
/// thousandth of the model's height) removed, with the vertices (colours, uvs) only they used.
ModelMesh above_plate(const ModelMesh& model, const SupportingPlate& plate);

/// The samples above the plate's top (by a thousandth of its thickness, or round-off).
SurfaceSamples samples_above(const SupportingPlate& plate, const SurfaceSamples& samples);

} // namespace popup
