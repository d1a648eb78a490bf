#pragma once
// Internal: patch-against-patch crossing tests at one fold state. Implemented in the CGAL
// translation unit find_crossings.cpp; this header stays free of CGAL.
#include <array>
#include <vector>

#include "popup/simulation/check_validity.hpp"

namespace popup {

/// A patch prepared once per check: all loop vertices, boundary edges and a constrained
/// triangulation of its interior (indices into `vertices`).
struct PatchMesh {
    std::vector<Vec3> vertices;                ///< design state
    std::vector<std::array<int, 2>> edges;     ///< boundary edges (outer loop and holes)
    std::vector<std::array<int, 3>> triangles; ///< interior, from a CGAL CDT
};

/// Throws CGAL::Failure_exception naming the patch when a loop cannot be triangulated.
std::vector<PatchMesh> mesh_patches(const Scaffold& scaffold);

/// Pairs of patch indices worth testing: different rigid bodies, overlapping boxes.
std::vector<std::array<int, 2>> candidate_pairs(const std::vector<PatchMesh>& meshes,
                                                const std::vector<int>& body_of_patch,
                                                const FoldState& state, double margin);

/// Depth (mm) by which patches i and j pass through each other in `state`, or a value <= 0
/// when they only touch, stack or stay apart. `clearance` (mm) also flags a vertex of one patch
/// coming closer than that to the inside of the other.
double crossing_depth(const std::vector<PatchMesh>& meshes, const Scaffold& scaffold,
                      const FoldState& state, int i, int j, double tolerance, double clearance);

/// Signed distance of each vertex of patch i from the plane of patch j.
std::vector<double> side_of_plane(const std::vector<PatchMesh>& meshes, const Scaffold& scaffold,
                                  const FoldState& state, int i, int j);

} // namespace popup
