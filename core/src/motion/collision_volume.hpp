#pragma once
#include <array>
#include <vector>

#include "motion_mechanism.hpp"

namespace popup::motion {

/// An oriented box: centre, three orthonormal axes (columns) and half extents along them.
struct OrientedBox {
    Vec3 centre = Vec3::Zero();
    Mat3 axes = Mat3::Identity();
    Vec3 half = Vec3::Zero();
    std::array<Vec3, 8> corners() const;
};

/// Separating-axis test of two oriented boxes (the 15 axes: 3 + 3 face normals, 9 edge
/// crossings). Returns the depth of overlap, the smallest overlap of the two boxes' shadows over
/// those axes (mm): 0 when some axis separates them (touching counts as separate), > 0 when they
/// intersect. That depth is the D_c of eq 6.8.
double overlap_depth(const OrientedBox& a, const OrientedBox& b);

/// Collision Bounding Volume (thesis §6.4.2): the room a mechanism's patches may take while the
/// card closes. One box per band of fold angles (the thesis merges convex hulls over angles; a
/// band of its own per angle range keeps two mechanisms that pass the same place at different
/// angles apart). Each box bounds the closed-form vertices at the band's sampled angles, padded
/// by 0.6 of the largest move of a vertex between two samples (a vertex between samples stays
/// within half its arc, barely longer than the chord at 5° steps) and by `clearance`. Boxes are
/// axis-aligned in the card frame (an oriented box with identity axes).
struct CollisionVolume {
    std::vector<OrientedBox> bands; ///< band k covers θ in [π k / n, π (k + 1) / n]
};

struct VolumeOptions {
    int bands = 6;
    int samples_per_band = 6; ///< intervals per band (7 angles)
    double clearance = 0.5;   ///< mm added on every side (paper thickness and round-off)
};

CollisionVolume collision_volume(const MotionMechanism& m, const VolumeOptions& options = {});

/// Σ over bands of the overlap depth of two volumes built with the same options: 0 when they
/// never share room at the same fold angles.
double collision_depth(const CollisionVolume& a, const CollisionVolume& b);

} // namespace popup::motion
