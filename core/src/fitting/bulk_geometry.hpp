#pragma once
// Internal: samples in the card hinge's coordinates and their distance to a box standing on the
// page, shared by the bulk box and the bulk stack (docs/MATH.md, "The model's bulk").
#include <algorithm>
#include <cmath>
#include <vector>

#include "popup/fitting/prism_types.hpp"
#include "popup/fitting/surface_samples.hpp"

namespace popup::bulk {

struct Point {
    double a, s, t; ///< along the hinge, across, up (the host's coordinates)
};

/// [a0, a1] x [-d, d] x [t0, h]: a box centred across the hinge, from t0 (0 on the page, its
/// host's top for a box standing on another) up to h.
struct Box {
    double a0, a1, d, h, t0 = 0;
};

/// Distance from p to the surface of the box.
inline double to_surface(const Box& b, const Point& p)
{
    const double da = std::max({b.a0 - p.a, 0.0, p.a - b.a1});
    const double ds = std::max(std::abs(p.s) - b.d, 0.0);
    const double dt = std::max({b.t0 - p.t, 0.0, p.t - b.h});
    if (da > 0 || ds > 0 || dt > 0)
        return std::sqrt(da * da + ds * ds + dt * dt);
    return std::min({p.a - b.a0, b.a1 - p.a, b.d - std::abs(p.s), b.h - p.t, p.t - b.t0});
}

/// At most `at_most` of the samples (every k-th), in the card hinge's coordinates.
std::vector<Point> points_on(const SurfaceSamples& samples, const PrismHost& card, size_t at_most);

/// `count` + 1 evenly spaced quantiles of v (sorted on return), the minimum and maximum included.
std::vector<double> quantiles(std::vector<double> v, int count);

} // namespace popup::bulk
