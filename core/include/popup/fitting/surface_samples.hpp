#pragma once
#include <cstdint>
#include <vector>

#include "popup/input/model_mesh.hpp"

namespace popup {

/// Pseudo-vertices (thesis §5.1.1, after [SLCH11]): points spread evenly over a mesh's surface
/// with the outward normal of the face each lies on, so that sparse and dense parts of a mesh
/// weigh by their area, not by their vertex count.
struct SurfaceSamples {
    std::vector<Vec3> points;
    std::vector<Vec3> normals; ///< unit, the face's (counter-clockwise winding seen from outside)
    double spacing = 0.0;      ///< mean distance between neighbours: sqrt(area / count)
};

/// `count` points, area-weighted and stratified: the i-th lies in the i-th of `count` equal
/// slices of the cumulative surface area, at a random place inside it drawn from `seed`. Same
/// mesh and seed, same points. Degenerate (zero-area) triangles get none.
SurfaceSamples sample_surface(const ModelMesh& mesh, int count, std::uint64_t seed);

/// The samples moved by `transform` (a similarity: rotation times a uniform scale, then a
/// translation), normals turned with it.
SurfaceSamples transformed(const SurfaceSamples& samples, const Eigen::Matrix4d& transform);

} // namespace popup
