#include "popup/fitting/bulk_prism.hpp"

#include <algorithm>
#include <cmath>

#include "bulk_geometry.hpp"

namespace popup {
namespace bulk {

std::vector<Point> points_on(const SurfaceSamples& samples, const PrismHost& card, size_t at_most)
{
    const size_t step = std::max<size_t>(1, samples.points.size() / std::max<size_t>(1, at_most));
    std::vector<Point> out;
    for (size_t i = 0; i < samples.points.size(); i += step) {
        const Vec3 q = samples.points[i] - card.origin;
        out.push_back({q.dot(card.axis), q.dot(card.across), q.dot(card.up)});
    }
    return out;
}

std::vector<double> quantiles(std::vector<double> v, int count)
{
    std::sort(v.begin(), v.end());
    std::vector<double> q;
    for (int i = 0; i <= count; ++i)
        q.push_back(v[size_t(std::llround(double(i) / count * double(v.size() - 1)))]);
    return q;
}

} // namespace bulk

namespace {

using bulk::Box;
using bulk::Point;

/// Distance from p to the surface of the box or to the page t = 0.
double distance(const Box& b, const Point& p)
{
    return std::min(bulk::to_surface(b, p), std::abs(p.t));
}

double mean_distance(const Box& b, const std::vector<Point>& points)
{
    double sum = 0;
    for (const Point& p : points)
        sum += distance(b, p);
    return points.empty() ? 0.0 : sum / double(points.size());
}

/// The box within the card and at least min_part in every dimension.
Box feasible(Box b, const PrismHost& card, double min_part)
{
    const double reach = std::min(card.across_max, -card.across_min);
    b.d = std::clamp(b.d, std::min(min_part, reach), reach);
    b.h = std::max(b.h, min_part);
    b.a0 = std::clamp(b.a0, 0.0, card.length);
    b.a1 = std::clamp(b.a1, 0.0, card.length);
    if (b.a1 - b.a0 < min_part) {
        const double mid =
            std::clamp(0.5 * (b.a0 + b.a1), 0.5 * min_part, card.length - 0.5 * min_part);
        b.a0 = mid - 0.5 * min_part;
        b.a1 = mid + 0.5 * min_part;
    }
    return b;
}

} // namespace

BulkBox bulk_box(const SurfaceSamples& samples, const PrismHost& card, double min_part)
{
    BulkBox out;
    Prism& m = out.prism;
    m.kind = Prism::Kind::rectangular;
    m.host = 0;
    const std::vector<Point> points = bulk::points_on(samples, card, 3000);
    if (points.empty())
        return out;
    std::vector<double> along, across, up;
    for (const Point& p : points) {
        along.push_back(p.a);
        across.push_back(std::abs(p.s));
        up.push_back(std::max(p.t, 0.0));
    }
    constexpr int kSteps = 40;
    const std::vector<double> qa = bulk::quantiles(along, kSteps),
                              qs = bulk::quantiles(across, kSteps),
                              qt = bulk::quantiles(up, kSteps);
    // Start from the middle half of the samples along and the median across and up.
    Box best = feasible({qa[kSteps / 4], qa[3 * kSteps / 4], qs[kSteps / 2], qt[kSteps / 2]}, card,
                        min_part);
    double best_cost = mean_distance(best, points);
    // Coordinate descent: each dimension in turn takes the quantile that lowers the mean most;
    // it stops when a round changes nothing (the cost only decreases: it ends).
    for (int round = 0; round < 12; ++round) {
        bool moved = false;
        for (int dim = 0; dim < 4; ++dim) {
            const std::vector<double>& candidates = dim < 2 ? qa : dim == 2 ? qs : qt;
            for (double v : candidates) {
                Box b = best;
                (dim == 0 ? b.a0 : dim == 1 ? b.a1 : dim == 2 ? b.d : b.h) = v;
                if (b.a1 <= b.a0)
                    continue;
                b = feasible(b, card, min_part);
                const double cost = mean_distance(b, points);
                if (cost < best_cost - 1e-12) {
                    best = b;
                    best_cost = cost;
                    moved = true;
                }
            }
        }
        if (!moved)
            break;
    }
    m.a0 = best.a0;
    m.a1 = best.a1;
    m.s0 = -best.d;
    m.s1 = best.d;
    m.height = best.h;
    out.mean_distance = best_cost;
    for (const Point& p : points)
        out.page_distance += std::abs(p.t) / double(points.size());
    return out;
}

} // namespace popup
