// Search's shaping of a candidate: grown along the hinge, then refitted to its inliers.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>

#include "prism_acceptance.hpp"
#include "prism_candidates.hpp"
#include "prism_scoring.hpp"

namespace popup::prism_search {
namespace {

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// Least-squares line through section points: returns a point and a unit direction.
bool fit_line(const std::vector<Vec2>& q, Vec2& point, Vec2& direction)
{
    if (q.size() < 2)
        return false;
    Vec2 c = Vec2::Zero();
    for (const Vec2& p : q)
        c += p;
    c /= double(q.size());
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    for (const Vec2& p : q)
        cov += (p - c) * (p - c).transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(cov);
    point = c;
    direction = solver.eigenvectors().col(1);
    return true;
}

} // namespace

void Search::extend_along(Prism& m, const std::vector<Local>& subset, double gap,
                          const PrismHost& h) const
{
    Prism open = m;
    open.a0 = -1e300;
    open.a1 = 1e300;
    const Section sec = section_of(open);
    std::vector<double> along;
    // A wall across the hinge inside the section, standing on the host, stops the growth
    // before it: past an L's inner corner the same top and front belong to another part
    // (the prism would enclose that wall). A wall higher up (a cab on a chassis) is a part
    // on top of a lower one; the volumetric test judges the grown prism then.
    std::vector<std::pair<double, double>> walls; // (a, t) of such samples
    for (const Local& q : subset) {
        int face = -1;
        const Where w = classify(open, sec, q, o_.threshold, h.flat, &face);
        if (w == Where::face && face <= 2)
            along.push_back(q.a);
        else if (w == Where::inside && std::abs(q.na) > kNormalAgreement &&
                 (q.a < m.a0 || q.a > m.a1))
            walls.push_back({q.a, q.t});
    }
    std::sort(walls.begin(), walls.end());
    double stop_lo = -1e300, stop_hi = 1e300;
    for (size_t i = 0; i < walls.size();) {
        size_t j = i;
        double lowest = walls[i].second;
        while (j + 1 < walls.size() && walls[j + 1].first - walls[j].first <= o_.threshold)
            lowest = std::min(lowest, walls[++j].second);
        if (lowest < 0.25 * m.height) {
            if (walls[i].first < m.a0)
                stop_lo = std::max(stop_lo, walls[j].first);
            else
                stop_hi = std::min(stop_hi, walls[i].first);
        }
        i = j + 1;
    }
    along.erase(std::remove_if(along.begin(), along.end(),
                               [&](double a) { return a <= stop_lo || a >= stop_hi; }),
                along.end());
    if (along.empty())
        return;
    std::sort(along.begin(), along.end());
    auto lo = std::lower_bound(along.begin(), along.end(), m.a0);
    if (lo == along.end())
        return;
    size_t i = size_t(lo - along.begin());
    while (i > 0 && along[i] - along[i - 1] <= gap)
        --i;
    auto hi = std::upper_bound(along.begin(), along.end(), m.a1);
    size_t j = hi == along.begin() ? 0 : size_t(hi - along.begin()) - 1;
    while (j + 1 < along.size() && along[j + 1] - along[j] <= gap)
        ++j;
    m.a0 = std::min(m.a0, along[i]);
    m.a1 = std::max(m.a1, along[j]);
    // Grown up to the wall that stopped it: the part ends on that wall (the scoring subset
    // is sparse, its last face sample falls short of it).
    if (m.a0 - stop_lo <= gap)
        m.a0 = stop_lo;
    if (stop_hi - m.a1 <= gap)
        m.a1 = stop_hi;
}

void Search::refit(Prism& m, const std::vector<Local>& l, const std::vector<int>& subset,
                   const PrismHost& h) const
{
    for (int round = 0; round < 3; ++round) {
        const Section sec = section_of(m);
        std::array<std::vector<double>, 5> coord;
        std::vector<Vec2> slope_g, slope_b;
        for (int i : subset) {
            int f = -1;
            if (classify(m, sec, l[i], o_.threshold, h.flat, &f) != Where::face)
                continue;
            const Local& q = l[i];
            if (f == 5) {
                continue; // the backbone stays on the hinge
            } else if (m.kind == Prism::Kind::rectangular) {
                const double c[5] = {q.t, q.s, q.s, q.a, q.a};
                coord[f].push_back(c[f]);
            } else if (f == 0) {
                slope_g.push_back({q.s, q.t});
            } else if (f == 2) {
                slope_b.push_back({q.s, q.t});
            } else {
                coord[f].push_back(q.a);
            }
        }
        Prism next = m;
        if (m.kind == Prism::Kind::rectangular) {
            // The sides' upper edge where nothing of the model lies on the top (a box
            // under a roof): the ends would otherwise pull it up the gables.
            std::vector<double> side_t;
            for (int i : subset) {
                int f = -1;
                if (classify(m, sec, l[i], o_.threshold, h.flat, &f) == Where::face &&
                    (f == 1 || f == 2))
                    side_t.push_back(l[i].t);
            }
            if (coord[0].size() * 10 >= side_t.size() && !coord[0].empty()) {
                next.height = median(coord[0]);
            } else if (side_t.size() >= 8) {
                next.height = *std::max_element(side_t.begin(), side_t.end());
            }
            if (h.flat) {
                std::vector<double> depth;
                for (double s : coord[1])
                    depth.push_back(s);
                for (double s : coord[2])
                    depth.push_back(-s);
                if (!depth.empty()) {
                    next.s1 = median(depth);
                    next.s0 = -next.s1;
                }
            } else if (!coord[1].empty()) {
                next.s1 = median(coord[1]);
            }
        } else {
            Vec2 pg, dg, pb, db;
            if (fit_line(slope_g, pg, dg) && fit_line(slope_b, pb, db)) {
                Prism t = next;
                if (triangle_from_lines(h, pg, dg, pb, db, o_.threshold, t))
                    next = t;
            }
        }
        if (!coord[3].empty())
            next.a0 = median(coord[3]);
        if (!coord[4].empty())
            next.a1 = median(coord[4]);
        if (!fit_host(h, next, o_.threshold, o_.min_part) ||
            outside_model(next, h, box_, o_.threshold))
            return;
        m = next;
    }
}

} // namespace popup::prism_search
