#pragma once
// The data of the primitive search (prism_ransac.hpp): hosts, prisms, its options and result.
// Below the search, so that its stages do not include it.
#include <cstdint>
#include <string>
#include <vector>

#include "popup/geometry/pose.hpp"
#include "popup/model/cancel_flag.hpp"

namespace popup {

/// A base patch pair as the primitive fitting sees it (thesis §5.1.1, Constraint 3): a hinge
/// along `axis` from `origin`, the page direction `across` and the direction `up` away from it.
/// Flat pairs (180°: the card, a box's top) carry prisms standing on them, centred on the hinge
/// across it; right-angle pairs (90°: a box's side and the page beyond it) carry prisms in the
/// corner, `across` along the page and `up` along the wall.
struct PrismHost {
    std::string name; ///< "central fold", or "<primitive>.top", ".side_ground", ".side_backdrop"
    int parent = -1;  ///< index of the primitive that offered it, -1 for the card
    std::string part; ///< "", "top", "side_ground" or "side_backdrop"
    bool flat = true;
    Vec3 origin = Vec3::Zero();
    Vec3 axis = Vec3::UnitY();
    Vec3 across = Vec3::UnitX();
    Vec3 up = Vec3::UnitZ();
    double length = 0.0;     ///< usable hinge length (mm)
    double across_min = 0.0; ///< flat: -backdrop depth; right angle: 0
    double across_max = 0.0; ///< flat: ground depth; right angle: the page beyond the wall
    double up_max = 1e300;   ///< right angle: the wall's height
};

/// A prism standing on a host, in the host's coordinates (a along the hinge, s across, t up).
/// Rectangular: s in [s0, s1], t in [0, height]. Triangular (flat hosts only): feet at s0 < 0 <
/// s1 on the host, apex at (apex_s, height). Both span a in [a0, a1]; side edges run along the
/// hinge (parallel to the fold) and the section is across it (Constraints 1 and 2).
struct Prism {
    enum class Kind { rectangular, triangular };
    Kind kind = Kind::rectangular;
    int host = 0;
    double a0 = 0, a1 = 0;
    double s0 = 0, s1 = 0;
    double height = 0;
    double apex_s = 0;
    int inliers = 0;

    const char* kind_name() const
    {
        return kind == Kind::rectangular ? "rectangular" : "triangular";
    }
    /// Corners in the card frame: 8 (rectangular: bottom a0, bottom a1, top a0, top a1, each
    /// s0 then s1) or 6 (triangular: a0 then a1, each s0 foot, s1 foot, apex).
    std::vector<Vec3> corners(const PrismHost& host) const;
};

struct RansacOptions {
    double min_points = 50;    ///< τ as a number of samples: the smallest prism worth finding
    double probability = 0.99; ///< p_t of the stopping rule
    double threshold = 1.0;    ///< ε: point-to-face tolerance (mm)
    std::uint64_t seed = 1;
    int max_primitives = 8;
    /// Thinnest prism accepted (mm) along the hinge, across (each side of the hinge on a flat
    /// host) and up: thinner mechanism parts get no glue tab on the cutting sheets.
    double min_part = 0.0;
    long max_draws = 100000; ///< safety bound on minimal samples drawn in one search
    /// Per sample, or empty: inside the model's volume (outer_surface: a face between touching
    /// parts, a box's top under its roof). Such samples may carry a prism's face but never
    /// refuse a prism that encloses them.
    std::vector<bool> inner;
    const CancelFlag* cancel = nullptr;
    /// Cores the draws may use (1 or 2): the same prisms either way. search_primitives gives
    /// 2 to a single alignment's search (several already run two at a time).
    int lanes = 1;
};

struct RansacResult {
    std::vector<PrismHost> hosts; ///< the card's pair first, then as primitives offer them
    std::vector<Prism> prisms;    ///< in the order found (hosts before what they carry)
    std::vector<int> owner;       ///< per sample: the prism it is an inlier of, or -1
    std::vector<bool> on_base;    ///< per sample: lies on a host's plane (under a prism)
    /// Per sample: lies on a face of its prism that its mechanism makes of paper (a top, a
    /// side, a slope, a box's backbone), not on an end across the hinge.
    std::vector<bool> on_principal;
    long draws = 0;                      ///< minimal samples drawn
    bool stopped_by_probability = false; ///< P(τ, C) > p_t ended the search
};

} // namespace popup
