#pragma once
// Internal: the samples of a model's outer surface, facing out (docs/MATH.md, "The model's
// volume"): what a pop-up can show of an assembly, a hollow shell or a soup of sheets.
#include "occupancy_grid.hpp"
#include "popup/fitting/surface_samples.hpp"

namespace popup {

struct OuterSurface {
    SurfaceSamples samples;  ///< every sample, the outer ones' normals turned to face out
    std::vector<bool> inner; ///< per sample: solid on both sides (a wall between two parts)
    int inner_count = 0;     ///< samples inside the volume
    int turned = 0;          ///< normals turned: they pointed into the volume
};

/// Each sample stepped two cells along its normal both ways: solid on both sides, it lies inside
/// the volume (a face between touching parts, the top of a box under a roof, an inner part, a
/// window's reveal once the window is closed) and is flagged inner; solid ahead and free behind,
/// its normal is turned round (a part whose winding the file or the cleaning reversed); otherwise
/// it is kept as it is (an outer face, or a sheet thinner than the step, open on both sides).
OuterSurface outer_surface(const OccupancyGrid& volume, const SurfaceSamples& samples);

/// The outer samples alone (all of them when every one is inner), at the same spacing: what the
/// model looks like from outside. A building's floor slabs, every storey a plane across the whole
/// footprint, would mirror onto each other under any plane and make a false mirror plane.
SurfaceSamples outer_only(const OuterSurface& surface);

/// The model with its faces turned to face out (`turned` counts them), so that a part whose
/// winding the file or the cleaning reversed faces out again and the model's up and flat ends
/// read true: a closed part (joined across edges two triangles share) turns whole when it bounds
/// a negative volume; a face of an open part turns when its centre, stepped two cells along its
/// normal, lands in the volume ahead and out of it behind.
ModelMesh faces_turned_out(const ModelMesh& model, const OccupancyGrid& volume, int& turned);

} // namespace popup
