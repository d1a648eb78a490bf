#pragma once
#include "popup/input/model_mesh.hpp"
#include "popup/model/result.hpp"

namespace popup {

/// What clean_model repaired, one count per kind, and what it could not repair (the border).
struct RepairCounts {
    int duplicate_points_merged = 0;     ///< vertices at the position of an earlier one
    int degenerate_faces_removed = 0;    ///< repeated corners, or no area (collinear corners)
    int duplicate_faces_removed = 0;     ///< the same corners as an earlier face, either winding
    int faces_reoriented = 0;            ///< faces whose winding the result reverses
    int non_manifold_vertices_split = 0; ///< vertices copied so each has one fan of faces
    int isolated_vertices_removed = 0;   ///< vertices no face uses
    int border_edges = 0;                ///< edges with a face on one side only
    int holes = 0;                       ///< closed loops of border edges
    bool closed = false;                 ///< no border: the mesh bounds a volume
};

struct CleanedModel {
    ModelMesh mesh;
    RepairCounts repairs;
};

/// Repairs a model with CGAL Polygon Mesh Processing (thesis §5.1 takes a clean surface): the
/// triangles as a polygon soup lose duplicate points, repeated-corner and duplicate faces and
/// unused points; the soup is oriented consistently (non-manifold vertices copied) and becomes a
/// mesh; faces without area are removed; a closed mesh is oriented to bound its volume (normals
/// outward), an open one keeps the winding of most of its input area.
/// The result keeps the source and base colour but no per-vertex colours, texture coordinates or
/// texture: merging vertices leaves them no single value; artwork reads the original mesh.
/// Errors: check_model's on the input; degenerate_model if no face survives.
Result<CleanedModel> clean_model(const ModelMesh& mesh);

} // namespace popup
