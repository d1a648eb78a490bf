#include "bulk_stack.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <future>
#include <vector>

#include "bulk_geometry.hpp"

namespace popup {
namespace {

using bulk::Box;
using bulk::Point;

constexpr int kSteps = 40;        ///< quantiles per coordinate, as bulk_box's
constexpr double kTentGain = 0.9; ///< a tent on top instead of a box when a tenth closer

/// The lower box on the page and the upper part from its top up: a box, or a tent (a roof)
/// whose feet are at ±d and whose ridge runs over the hinge at h.
struct Stack {
    Box lower, upper;
    bool tent = false;
};

double to_segment(double s, double t, double s0, double t0, double s1, double t1)
{
    const double es = s1 - s0, et = t1 - t0;
    const double u = std::clamp(((s - s0) * es + (t - t0) * et) / (es * es + et * et), 0.0, 1.0);
    return std::hypot(s - s0 - u * es, t - t0 - u * et);
}

/// Distance from p to the tent's two slopes from (±d, base) to (0, h), along a from a0 to a1.
double to_tent(const Box& b, double base, const Point& p)
{
    const double da = std::max({b.a0 - p.a, 0.0, p.a - b.a1});
    const double section = to_segment(std::abs(p.s), p.t, b.d, base, 0.0, b.h);
    return std::hypot(da, section);
}

double mean_distance(const Stack& k, const std::vector<Point>& points)
{
    Box upper = k.upper;
    upper.t0 = k.lower.h;
    double sum = 0;
    for (const Point& p : points) {
        const double up = k.tent ? to_tent(upper, k.lower.h, p) : bulk::to_surface(upper, p);
        sum += std::min({bulk::to_surface(k.lower, p), up, std::abs(p.t)});
    }
    return points.empty() ? 0.0 : sum / double(points.size());
}

/// Within the card, every dimension at least min_part, the upper box on the lower's top.
bool feasible(const Stack& k, const PrismHost& card, double min_part)
{
    const Box &lo = k.lower, &up = k.upper;
    const double reach = std::min(card.across_max, -card.across_min);
    // A tent's feet lie strictly inside its host's pages (prism_candidates' 0.5 %).
    const double widest = k.tent ? 0.995 * lo.d : lo.d;
    return lo.a0 >= 0 && lo.a1 <= card.length && lo.a1 - lo.a0 >= min_part && lo.d <= reach &&
           lo.h >= min_part && up.d >= min_part && up.d <= widest && up.a0 >= lo.a0 &&
           up.a1 <= lo.a1 && up.a1 - up.a0 >= min_part && up.h - lo.h >= min_part;
}

double& parameter(Stack& k, int dim)
{
    Box& b = dim < 4 ? k.lower : k.upper;
    const int d = dim % 4;
    return d == 0 ? b.a0 : d == 1 ? b.a1 : d == 2 ? b.d : b.h;
}

/// Coordinate descent from `start` (each parameter in turn takes the candidate that lowers the
/// mean most, until a round changes nothing); its cost in `cost`.
Stack descend(Stack best, const std::vector<Point>& points,
              const std::array<std::vector<double>, 3>& all,
              const std::array<std::vector<double>, 3>& above, const PrismHost& card,
              double min_part, double& best_cost)
{
    best_cost = mean_distance(best, points);
    for (int round = 0; round < 12; ++round) {
        bool moved = false;
        for (int dim = 0; dim < 8; ++dim) {
            const int coordinate = std::min(dim % 4, 2); // a0 and a1 both along
            for (const auto* candidates : {&all[coordinate], &above[coordinate]})
                for (double v : *candidates) {
                    Stack k = best;
                    parameter(k, dim) = v;
                    if (!feasible(k, card, min_part))
                        continue;
                    const double cost = mean_distance(k, points);
                    if (cost < best_cost - 1e-12) {
                        best = k;
                        best_cost = cost;
                        moved = true;
                    }
                }
        }
        if (!moved)
            break;
    }
    return best;
}

std::array<std::vector<double>, 3> quantiles_of(const std::vector<Point>& points, double above)
{
    std::vector<double> a, s, t;
    for (const Point& p : points)
        if (p.t > above) {
            a.push_back(p.a);
            s.push_back(std::abs(p.s));
            t.push_back(std::max(p.t, 0.0));
        }
    if (a.empty())
        return {};
    return {bulk::quantiles(a, kSteps), bulk::quantiles(s, kSteps), bulk::quantiles(t, kSteps)};
}

} // namespace

std::optional<BulkStack> bulk_stack(const SurfaceSamples& samples, const PrismHost& card,
                                    double min_part, const BulkBox& single)
{
    const std::vector<Point> points = bulk::points_on(samples, card, 1500);
    const Prism& m = single.prism;
    const std::array<std::vector<double>, 3> all = quantiles_of(points, -1e300);
    if (all[0].empty())
        return std::nullopt;
    // Starts: the lower box the single one cut at each of several heights of the samples, the
    // upper box over the middle of the samples above the cut, up to their 90th percentile.
    // A box on top unless a tent lies a tenth closer: a roof is a clear win, while a tent over
    // a spider's legs only rounds off a box whose sides would have shown them in outline.
    // Each start descends on its own, two at a time on the two cores; compared in order after.
    struct Start {
        Stack stack;
        std::array<std::vector<double>, 3> above;
        double cost = 1e300;
    };
    std::vector<Start> starts;
    for (bool tent : {false, true})
        for (int cut :
             {kSteps * 4 / 10, kSteps / 2, kSteps * 6 / 10, kSteps * 7 / 10, kSteps * 8 / 10}) {
            const double h = all[2][size_t(cut)];
            std::array<std::vector<double>, 3> above = quantiles_of(points, h);
            if (above[0].empty())
                continue;
            Stack start{{m.a0, m.a1, m.s1, h}, {}, tent};
            start.upper = {std::max(above[0][kSteps / 10], m.a0),
                           std::min(above[0][9 * kSteps / 10], m.a1),
                           std::min(std::max(above[1][kSteps / 2], min_part), m.s1),
                           std::max(above[2][9 * kSteps / 10], h + min_part)};
            if (tent) // a roof's feet at the top's edges, its ridge at the highest samples
                start.upper = {start.upper.a0, start.upper.a1, 0.995 * m.s1,
                               std::max(above[2][kSteps], h + min_part)};
            if (feasible(start, card, min_part))
                starts.push_back({start, std::move(above)});
        }
    std::atomic<size_t> next{0};
    auto descend_next = [&] {
        for (size_t k = next++; k < starts.size(); k = next++)
            starts[k].stack = descend(starts[k].stack, points, all, starts[k].above, card, min_part,
                                      starts[k].cost);
    };
    std::future<void> other = std::async(std::launch::async, descend_next);
    descend_next();
    other.get();
    std::optional<Stack> best;
    double best_cost = 1e300;
    for (bool tent : {false, true}) {
        std::optional<Stack> best_of_kind;
        double kind_cost = 1e300;
        for (const Start& k : starts)
            if (k.stack.tent == tent && k.cost < kind_cost) {
                best_of_kind = k.stack;
                kind_cost = k.cost;
            }
        if (best_of_kind && kind_cost < (tent ? kTentGain : 1.0) * best_cost) {
            best = best_of_kind;
            best_cost = kind_cost;
        }
    }
    if (!best)
        return std::nullopt;
    BulkStack out;
    out.lower = single.prism;
    out.lower.a0 = best->lower.a0;
    out.lower.a1 = best->lower.a1;
    out.lower.s0 = -best->lower.d;
    out.lower.s1 = best->lower.d;
    out.lower.height = best->lower.h;
    out.upper.kind = best->tent ? Prism::Kind::triangular : Prism::Kind::rectangular;
    out.upper.apex_s = 0;
    out.upper.host = 1;
    out.upper.a0 = best->upper.a0 - best->lower.a0;
    out.upper.a1 = best->upper.a1 - best->lower.a0;
    out.upper.s0 = -best->upper.d;
    out.upper.s1 = best->upper.d;
    out.upper.height = best->upper.h - best->lower.h;
    out.mean_distance = best_cost;
    return out;
}

} // namespace popup
