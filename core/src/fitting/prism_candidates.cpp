#include "prism_candidates.hpp"

#include <algorithm>
#include <cmath>

#include "prism_acceptance.hpp"

namespace popup::prism_search {

bool triangle_from_lines(const PrismHost& h, Vec2 p1, Vec2 d1, Vec2 p2, Vec2 d2, double eps,
                         Prism& m)
{
    if (std::abs(d1.y()) < 1e-9 || std::abs(d2.y()) < 1e-9)
        return false;
    const double f1 = p1.x() - p1.y() * d1.x() / d1.y(); // where each line meets t = 0
    const double f2 = p2.x() - p2.y() * d2.x() / d2.y();
    const double cross = d1.x() * d2.y() - d1.y() * d2.x();
    if (std::abs(cross) < 1e-9)
        return false;
    const Vec2 w = p2 - p1;
    const double u = (w.x() * d2.y() - w.y() * d2.x()) / cross;
    const Vec2 apex = p1 + u * d1;
    m.s1 = std::max(f1, f2);
    m.s0 = std::min(f1, f2);
    m.apex_s = apex.x();
    m.height = apex.y();
    // A tent's feet lie on both sides of its hinge, strictly inside the host's pages (its
    // generator's ranges); feet at a page's edge (a roof on a box's eaves) step in by 0.5 %.
    const double inner = 0.995;
    if (m.s1 > inner * h.across_max && m.s1 < h.across_max + eps)
        m.s1 = inner * h.across_max;
    if (m.s0 < inner * h.across_min && m.s0 > h.across_min - eps)
        m.s0 = inner * h.across_min;
    return m.height > eps && m.s0 < 0 && 0 < m.s1 && m.s0 < m.apex_s && m.apex_s < m.s1 &&
           m.s0 > h.across_min && m.s1 < h.across_max && m.s1 - m.s0 > eps;
}

Draw draw_sample(const Round& round, const DrawInputs& in, std::mt19937_64& rng,
                 std::uniform_int_distribution<size_t>& pick_point,
                 std::uniform_int_distribution<int>& pick_level)
{
    Draw d;
    d.p1 = round.starts[pick_point(rng)];
    const int hosts = int(in.hosts.size());
    auto eligible = [&](int h) { return above_host(in.hosts[h], in.locals[h][d.p1], in.eps); };
    size_t count = 0;
    for (int h = 0; h < hosts; ++h)
        count += eligible(h);
    const int level = pick_level(rng);
    d.p2 = in.cells.pick(d.p1, level, rng);
    d.p3 = in.cells.pick(d.p1, level, rng);
    d.p4 = in.cells.pick(d.p1, level, rng);
    if (count == 0)
        return d;
    // The host: the chosen one of those eligible, in their order.
    std::uniform_int_distribution<size_t> pick_host(0, count - 1);
    size_t chosen = pick_host(rng);
    for (int h = 0; h < hosts; ++h)
        if (eligible(h) && chosen-- == 0) {
            d.host = h;
            break;
        }
    return d;
}

void draw_candidates(const Round& round, const DrawInputs& in, std::mt19937_64& rng,
                     std::uniform_int_distribution<size_t>& pick_point,
                     std::uniform_int_distribution<int>& pick_level, Candidates& found)
{
    try_candidates(draw_sample(round, in, rng, pick_point, pick_level), round, in, found);
}

void try_candidates(const Draw& d, const Round& round, const DrawInputs& in, Candidates& found)
{
    if (d.host < 0)
        return;
    const int h = d.host, p1 = d.p1, p2 = d.p2, p3 = d.p3, p4 = d.p4;
    const PrismHost& host = in.hosts[h];
    const auto& l = in.locals[h];
    if (!above_host(host, l[p2], in.eps))
        return;
    // Rectangular: two points fix the top and the sides (Fig 5.4).
    Prism rect;
    rect.kind = Prism::Kind::rectangular;
    rect.host = h;
    rect.height = std::max(l[p1].t, l[p2].t);
    rect.s1 =
        host.flat ? std::max(std::abs(l[p1].s), std::abs(l[p2].s)) : std::max(l[p1].s, l[p2].s);
    rect.s0 = host.flat ? -rect.s1 : 0.0;
    rect.a0 = std::min(l[p1].a, l[p2].a);
    rect.a1 = std::max(l[p1].a, l[p2].a);
    if (fit_host(host, rect, in.eps, in.min_part)) {
        const double seed_a0 = rect.a0, seed_a1 = rect.a1;
        in.search.extend_along(rect, round.box_sub[h], round.gap, host);
        stop_at_taken(rect, host, in.taken, seed_a0, seed_a1, in.eps);
        if (fit_host(host, rect, in.eps, in.min_part)) {
            const double sc = in.search.score(rect, round.box_sub[h], round.grd[h], host.flat,
                                              round.scale, found.best_rect.score);
            if (sc > found.best_rect.score && !overlaps(rect, host, in.taken, in.eps) &&
                !outside_model(rect, host, in.model, in.eps))
                found.best_rect = {rect, sc};
        }
    }
    // Triangular: two points on each slope (Fig 5.4), flat hosts only.
    if (!host.flat || !above_host(host, l[p3], in.eps) || !above_host(host, l[p4], in.eps))
        return;
    ++found.tri_draws;
    const Vec2 q1(l[p1].s, l[p1].t), q2(l[p2].s, l[p2].t), q3(l[p3].s, l[p3].t),
        q4(l[p4].s, l[p4].t);
    if ((q2 - q1).norm() < in.eps || (q4 - q3).norm() < in.eps)
        return;
    Prism tri;
    tri.kind = Prism::Kind::triangular;
    tri.host = h;
    if (!triangle_from_lines(host, q1, (q2 - q1).normalized(), q3, (q4 - q3).normalized(), in.eps,
                             tri))
        return;
    tri.a0 = std::min({l[p1].a, l[p2].a, l[p3].a, l[p4].a});
    tri.a1 = std::max({l[p1].a, l[p2].a, l[p3].a, l[p4].a});
    if (!fit_host(host, tri, in.eps, in.min_part))
        return;
    const double seed_a0 = tri.a0, seed_a1 = tri.a1;
    in.search.extend_along(tri, round.tent_sub[h], round.gap, host);
    stop_at_taken(tri, host, in.taken, seed_a0, seed_a1, in.eps);
    if (!fit_host(host, tri, in.eps, in.min_part))
        return;
    const double sc = in.search.score(tri, round.tent_sub[h], round.grd[h], true, round.scale,
                                      found.best_tri.score);
    if (sc > found.best_tri.score && !overlaps(tri, host, in.taken, in.eps) &&
        !outside_model(tri, host, in.model, in.eps))
        found.best_tri = {tri, sc};
}

void keep_better(Candidates& found, const Candidates& later)
{
    // Each kind's best is the first of the highest score: the later batch's only if higher.
    if (later.best_rect.score > found.best_rect.score)
        found.best_rect = later.best_rect;
    if (later.best_tri.score > found.best_tri.score)
        found.best_tri = later.best_tri;
}

} // namespace popup::prism_search
