#pragma once
// Internal: patch-against-patch crossing tests at one fold state. Implemented in the CGAL
// translation unit find_crossings.cpp; this header stays free of CGAL.
#include <array>
#include <vector>

#include "popup/simulation/fold_state.hpp"

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

/// A fold state with the mesh vertices of its patches placed once: every pair test, the pair
/// search and the pass-through test read them instead of posing the same vertices again.
struct PosedPatches {
    const FoldState* state = nullptr;
    std::vector<std::vector<Vec3>> vertices; ///< per patch; empty for patches left out
};

/// Poses every patch's mesh vertices at `state`, or only those of `only` (patch indices), into
/// `posed` (its buffers are reused: the validity check poses two states per sample).
void pose_patches(const std::vector<PatchMesh>& meshes, const FoldState& state, PosedPatches& posed,
                  const std::vector<int>& only = {});
inline PosedPatches pose_patches(const std::vector<PatchMesh>& meshes, const FoldState& state,
                                 const std::vector<int>& only = {})
{
    PosedPatches posed;
    pose_patches(meshes, state, posed, only);
    return posed;
}

/// Pairs of patch indices worth testing: different rigid bodies, overlapping boxes.
std::vector<std::array<int, 2>>
candidate_pairs(const PosedPatches& posed, const std::vector<int>& body_of_patch, double margin);

/// Depth (mm) by which patches i and j pass through each other in `posed`'s state, or a value
/// <= 0 when they only touch, stack or stay apart. `clearance` (mm) also flags a vertex of one
/// patch coming closer than that to the inside of the other. Patches i and j must be posed.
double crossing_depth(const std::vector<PatchMesh>& meshes, const PosedPatches& posed,
                      const Scaffold& scaffold, int i, int j, double tolerance, double clearance);

/// Signed distance of each vertex of patch i from the plane of patch j (i must be posed), into
/// `side`.
void side_of_plane(const PosedPatches& posed, const Scaffold& scaffold, int i, int j,
                   std::vector<double>& side);

} // namespace popup
