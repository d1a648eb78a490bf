#include "popup/motion/adaptive_samples.hpp"

#include <algorithm>
#include <cmath>

namespace popup {

namespace {

/// Turning angle (radians) at q between a->q and q->b; 0 when either piece is shorter than still.
double turn(const Vec2& a, const Vec2& q, const Vec2& b, double still)
{
    const Vec2 u = q - a, v = b - q;
    if (u.norm() <= still || v.norm() <= still)
        return 0.0;
    return std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v));
}

struct Sampler {
    const std::function<Vec2(double)>& path;
    double tolerance;
    double still;
    int max_depth;
    std::vector<double> s;

    void split(double a, const Vec2& pa, double b, const Vec2& pb, int depth)
    {
        const double m = 0.5 * (a + b);
        const Vec2 q1 = path(0.75 * a + 0.25 * b), pm = path(m), q3 = path(0.25 * a + 0.75 * b);
        const double worst = std::max({turn(pa, q1, pm, still), turn(q1, pm, q3, still),
                                       turn(pm, q3, pb, still), turn(pa, pm, pb, still)});
        if (depth >= max_depth || !(worst > tolerance))
            return;
        split(a, pa, m, pm, depth + 1);
        s.push_back(m);
        split(m, pm, b, pb, depth + 1);
    }
};

} // namespace

std::vector<double> adaptive_samples(const std::function<Vec2(double)>& path, double tolerance_deg,
                                     double still, int max_depth)
{
    Sampler sampler{path, tolerance_deg * M_PI / 180.0, still, max_depth, {0.0}};
    sampler.split(0.0, path(0.0), 1.0, path(1.0), 0);
    sampler.s.push_back(1.0);
    return sampler.s;
}

} // namespace popup
