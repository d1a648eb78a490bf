#pragma once
#include <vector>

#include "popup/input/model_mesh.hpp"

namespace popup::testing {

/// Closed meshes with known answers for the fitting tests and benchmarks (issue 12 §5), built
/// programmatically. Coordinates: z up, the mirror plane x = 0, the length along y; every model
/// stands on z = 0.

/// A polygon (counter-clockwise in (x, z)) extruded along y from y0 to y1.
ModelMesh extrude_section(const std::vector<Vec2>& section_xz, double y0, double y1);
/// A polygon (counter-clockwise in (y, z)) extruded along x from -half to half.
ModelMesh extrude_elevation(const std::vector<Vec2>& elevation_yz, double half_x);
/// An axis-aligned box [lo, hi].
ModelMesh box_mesh(const Vec3& lo, const Vec3& hi);
/// Several closed meshes as one (touching, not merged: like a model made of parts).
ModelMesh join(const std::vector<ModelMesh>& parts);
/// Splits every triangle into four, `levels` times (more vertices, same surface).
ModelMesh subdivided(const ModelMesh& mesh, int levels);
/// Every triangle split into an n-by-n grid of triangles, n chosen so the mesh has about
/// `vertices` vertices (each triangle keeps its own grid: a soup, as many files are).
ModelMesh tessellated(const ModelMesh& mesh, int vertices);
/// The mesh moved by x -> scale * rotation * x + shift.
ModelMesh moved(const ModelMesh& mesh, const Mat3& rotation, double scale, const Vec3& shift);

/// 40 (x) by 120 (y) by 30 (z).
ModelMesh cuboid_model();
/// A 60 by 100 body 24 high under a ridge roof 18 high, ridge along y.
ModelMesh house_model();
/// Chassis 40 x 140 x 14; cargo box 40 x 80 x 36 and cab 40 x 36 x 24 on it, 16 apart.
ModelMesh truck_model();
/// A triangular prism: feet at x = ±30, apex 36 high, 110 long.
ModelMesh tent_model();
/// A box 40 x 100 x 30 with a low annex 15 deep and 12 high against each long side, over y in
/// [20, 70].
ModelMesh annexed_model();
/// An L in elevation: a wing 100 long and 24 high, a tower 30 long and 60 high at y = 0;
/// 40 deep.
ModelMesh l_building_model();

/// An L in plan, 30 high: a wing 60 (x) by 20 (y) along the front, and an arm 20 (x) by 50 (y)
/// from its left end to the back (tools/make_models.py's "l_building").
ModelMesh l_plan_model();

/// A UV sphere of `radius` at `centre` (segments around, rings from pole to pole).
ModelMesh sphere_mesh(const Vec3& centre, double radius, int segments = 32, int rings = 16);
/// A closed cylinder between two points.
ModelMesh cylinder_mesh(const Vec3& from, const Vec3& to, double radius, int segments = 24);
/// A figure of spheres and cylinders: body, head, arms and legs, standing on z = 0.
ModelMesh figure_model();
/// A squashed sphere (an ellipsoid 60 x 100 x 40) resting on z = 0.
ModelMesh blob_model();

} // namespace popup::testing
