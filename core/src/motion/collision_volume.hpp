#pragma once
#include <array>
#include <vector>

#include "mechanism_parts.hpp"

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
/// card closes. One set of bounds per band of fold angles (the thesis merges convex hulls over
/// angles; a band of its own per angle range keeps two mechanisms that pass the same place at
/// different angles apart). In each band every piece of paper (mechanism_parts: a patch, or its
/// part on one side of the fold's plane) is held by the convex hull of its closed-form vertices
/// at the band's sampled angles, grown along each axis by `pad`: half the largest second
/// difference of a vertex over neighbouring samples (which bounds the curve's departure from
/// the chords between samples) plus the clearance. Each piece also has its axis-aligned box (the
/// same points and pad), and each band one box around all its pieces, tested first.
///
/// Everything lives in the card frame with x divided by sin(θ/2) at each sample (docs/MATH.md,
/// "Tight collision volumes"): at a given angle that is a linear map, so pieces whose mapped
/// bounds are apart are apart; and it takes away the closing card's squeeze (every x → 0),
/// which would otherwise make every two pieces near the fold overlap in the bands near 0°.
struct CollisionVolume {
    std::vector<OrientedBox> bands;   ///< band k covers θ in [π k / n, π (k + 1) / n]
    std::vector<OrientedBox> aligned; ///< band-major: aligned[k * sides.size() + i], piece i
    std::vector<int> sides;           ///< per piece, MechanismPart::side
    /// The pieces' sampled vertices, band-major like `aligned`, one array per coordinate (the
    /// shadows' loops are the search's hot spot): piece i of band k holds points
    /// [first[k·n + i] .. first[k·n + i + 1]), every sample of the band, and lies within
    /// pad[k·n + i] (per axis) of their convex hull.
    std::vector<double> xs, ys, zs;
    std::vector<int> first;
    std::vector<Vec3> pad;
    /// Offsets the paper is also carried along (carry_along): each piece's hull is swept by them.
    std::vector<Vec3> carried;
    /// The separating-axis candidates of two convex polygons: each piece's plane normal at the
    /// band's middle angle (zero when degenerate) and the directions between its vertices there,
    /// edges[edge_first[k·n + i] .. edge_first[k·n + i + 1]), unit, one per direction.
    std::vector<Vec3> normals;
    std::vector<Vec3> edges;
    std::vector<int> edge_first;
};

struct VolumeOptions {
    int bands = 8;
    int samples_per_band = 2; ///< intervals per band (3 angles)
    double clearance = 0.5;   ///< mm added on every side (paper thickness and round-off)
};

CollisionVolume collision_volume(const MotionMechanism& m, const VolumeOptions& options = {});

/// The room the volume takes when its paper is also carried along each of `offsets` (a merged
/// patch that carries several parts): each piece's hull is swept by the offsets (`carried`),
/// its box grows to hold its copies moved by each; a piece keeps its side only when no offset
/// moves it across.
void carry_along(CollisionVolume& volume, const std::vector<Vec3>& offsets);

/// Collision depth D_c of eq 6.8 for two volumes built with the same options: Σ over bands of
/// the deepest overlap of two pieces, pieces on opposite sides of the fold's plane excepted. The
/// overlap of two pieces is the smaller of their boxes' overlap (overlap_depth) and the smallest
/// overlap of their padded points' shadows on the separating-axis candidates (both normals, the
/// crosses of their edges). 0 when they never share room at the same fold angles; in mm,
/// shrinking as they separate.
double collision_depth(const CollisionVolume& a, const CollisionVolume& b);

/// Whether collision_depth(a, b) > 0, stopping at the first two pieces that share room: the
/// annealing's hard constraint once it is collision-free needs only that answer.
bool collide(const CollisionVolume& a, const CollisionVolume& b);

} // namespace popup::motion
