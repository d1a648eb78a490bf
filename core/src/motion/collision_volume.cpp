#include "collision_volume.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace popup::motion {

std::array<Vec3, 8> OrientedBox::corners() const
{
    std::array<Vec3, 8> c;
    for (int k = 0; k < 8; ++k) {
        const Vec3 s((k & 1) ? 1.0 : -1.0, (k & 2) ? 1.0 : -1.0, (k & 4) ? 1.0 : -1.0);
        c[k] = centre + axes * s.cwiseProduct(half);
    }
    return c;
}

double overlap_depth(const OrientedBox& a, const OrientedBox& b)
{
    const Vec3 d = b.centre - a.centre;
    if (a.axes == Mat3::Identity() && b.axes == Mat3::Identity()) {
        // Two axis-aligned boxes (every collision volume): the 15 axes reduce to the three
        // coordinate axes (the edge crossings are ±e_k or zero), with the same overlaps.
        const Vec3 overlap = a.half + b.half - d.cwiseAbs();
        return overlap.minCoeff() <= 0 ? 0.0 : overlap.minCoeff();
    }
    double depth = std::numeric_limits<double>::infinity();
    // The shadow of a box on unit axis n has radius Σ half_i |axis_i · n|; the boxes overlap on
    // n by ra + rb − |d·n|.
    auto test = [&](const Vec3& axis) {
        const double len = axis.norm();
        if (len < 1e-9)
            return true; // parallel edges: the face axes decide
        const Vec3 n = axis / len;
        const double ra = a.half.x() * std::abs(a.axes.col(0).dot(n)) +
                          a.half.y() * std::abs(a.axes.col(1).dot(n)) +
                          a.half.z() * std::abs(a.axes.col(2).dot(n));
        const double rb = b.half.x() * std::abs(b.axes.col(0).dot(n)) +
                          b.half.y() * std::abs(b.axes.col(1).dot(n)) +
                          b.half.z() * std::abs(b.axes.col(2).dot(n));
        const double overlap = ra + rb - std::abs(d.dot(n));
        if (overlap <= 0)
            return false;
        depth = std::min(depth, overlap);
        return true;
    };
    for (int i = 0; i < 3; ++i)
        if (!test(a.axes.col(i)) || !test(b.axes.col(i)))
            return 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (!test(a.axes.col(i).cross(b.axes.col(j))))
                return 0.0;
    return depth;
}

CollisionVolume collision_volume(const MotionMechanism& m, const VolumeOptions& options)
{
    CollisionVolume v;
    const int n = std::max(1, options.bands), k = std::max(1, options.samples_per_band);
    std::vector<Vec3> previous, now;
    for (int band = 0; band < n; ++band) {
        Eigen::AlignedBox3d box;
        double chord = 0.0;
        // A band starts at the angle where the one before ended: its vertices are `previous`.
        const bool shared = band > 0;
        if (!shared)
            previous.clear();
        for (int i = 0; i <= k; ++i) {
            const double theta = M_PI * (band + double(i) / k) / n;
            if (i == 0 && shared)
                now.swap(previous);
            else
                now = mechanism_vertices(m, theta);
            for (std::size_t j = 0; j < now.size(); ++j) {
                box.extend(now[j]);
                if (i > 0 && j < previous.size())
                    chord = std::max(chord, (now[j] - previous[j]).norm());
            }
            previous.swap(now);
        }
        OrientedBox b;
        b.centre = box.center();
        b.half = box.sizes() / 2 + Vec3::Constant(0.6 * chord + options.clearance);
        v.bands.push_back(b);
    }
    return v;
}

double collision_depth(const CollisionVolume& a, const CollisionVolume& b)
{
    double sum = 0.0;
    const std::size_t n = std::min(a.bands.size(), b.bands.size());
    for (std::size_t k = 0; k < n; ++k)
        sum += overlap_depth(a.bands[k], b.bands[k]);
    return sum;
}

} // namespace popup::motion
