#include "popup/fitting/prism_ransac.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <map>
#include <random>

namespace popup {
namespace {

constexpr double kNormalAgreement = 0.94; ///< cos 20°: the largest normal deviation on a face
constexpr int kLevels = 5;                ///< cell sizes of the localised sampling

/// A sample in one host's coordinates.
struct Local {
    double a, s, t;    ///< along the hinge, across, up
    double na, ns, nt; ///< the normal in the same axes
};

Local to_local(const PrismHost& h, const Vec3& p, const Vec3& n)
{
    const Vec3 q = p - h.origin;
    return {q.dot(h.axis), q.dot(h.across), q.dot(h.up),
            n.dot(h.axis), n.dot(h.across), n.dot(h.up)};
}

bool above_host(const PrismHost& h, const Local& l, double eps)
{
    if (l.a < -eps || l.a > h.length + eps || l.t < eps * 0.5)
        return false;
    if (h.flat)
        return l.s > h.across_min - eps && l.s < h.across_max + eps;
    return l.s > eps * 0.5 && l.s < h.across_max + eps && l.t < h.up_max + eps;
}

/// Which face of a prism a sample lies on (within ε, normal agreeing), or inside it.
enum class Where { outside, face, inside };

struct Section {
    // Triangular: the two slopes as unit outward normals and a point on each.
    Vec2 ng, nb, g, b;
    double lg = 0, lb = 0; // slope lengths
};

Section section_of(const Prism& m)
{
    Section s;
    s.g = Vec2(m.s1, 0);
    s.b = Vec2(m.s0, 0);
    const Vec2 apex(m.apex_s, m.height);
    const Vec2 dg = apex - s.g, db = apex - s.b;
    s.lg = dg.norm();
    s.lb = db.norm();
    s.ng = Vec2(dg.y(), -dg.x()) / std::max(s.lg, 1e-300);
    s.nb = Vec2(-db.y(), db.x()) / std::max(s.lb, 1e-300);
    return s;
}

/// Face index: 0 top or ground slope, 1 side s1 (rect), 2 side s0 or backdrop slope, 3 end a0,
/// 4 end a1, 5 a rectangular prism's backbone (its hinge plane, s = 0, on a flat host).
Where classify(const Prism& m, const Section& sec, const Local& l, double eps, bool flat,
               int* face = nullptr)
{
    const bool in_a = l.a > m.a0 - eps && l.a < m.a1 + eps;
    if (!in_a)
        return Where::outside;
    const bool deep_a = l.a > m.a0 + eps && l.a < m.a1 - eps;
    auto set = [&](int f) {
        if (face)
            *face = f;
        return Where::face;
    };
    if (m.kind == Prism::Kind::rectangular) {
        const bool in_s = l.s > m.s0 - eps && l.s < m.s1 + eps;
        const bool in_t = l.t > -eps && l.t < m.height + eps;
        if (!in_s || !in_t)
            return Where::outside;
        // A box fold's backbone C stands on its hinge from the page to the top: a wall of the
        // model there (an L's inner wall with the fold on it) lies on the box, not inside it.
        if (flat && std::abs(l.s) < eps && std::abs(l.ns) > kNormalAgreement && l.t < m.height)
            return set(5);
        if (deep_a && l.s > m.s0 + eps && l.s < m.s1 - eps && l.t > eps && l.t < m.height - eps)
            return Where::inside;
        if (std::abs(l.t - m.height) < eps && l.nt > kNormalAgreement)
            return set(0);
        if (std::abs(l.s - m.s1) < eps && l.ns > kNormalAgreement)
            return set(1);
        if (flat && std::abs(l.s - m.s0) < eps && l.ns < -kNormalAgreement)
            return set(2);
        if (std::abs(l.a - m.a0) < eps && l.na < -kNormalAgreement)
            return set(3);
        if (std::abs(l.a - m.a1) < eps && l.na > kNormalAgreement)
            return set(4);
        return Where::outside;
    }
    const Vec2 q(l.s, l.t);
    const double dg = (q - sec.g).dot(sec.ng), db = (q - sec.b).dot(sec.nb);
    if (dg > eps || db > eps || l.t < -eps)
        return Where::outside;
    if (deep_a && dg < -eps && db < -eps && l.t > eps)
        return Where::inside;
    const Vec2 n(l.ns, l.nt);
    if (std::abs(dg) < eps && n.dot(sec.ng) > kNormalAgreement)
        return set(0);
    if (std::abs(db) < eps && n.dot(sec.nb) > kNormalAgreement)
        return set(2);
    if (std::abs(l.a - m.a0) < eps && l.na < -kNormalAgreement)
        return set(3);
    if (std::abs(l.a - m.a1) < eps && l.na > kNormalAgreement)
        return set(4);
    return Where::outside;
}

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

/// Feet and apex from the two slope lines; false unless they make a prism standing on the host.
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

/// Every dimension of the prism that becomes a glued crease is at least `min_part`: the length
/// along the hinge (every mechanism's patches are glued to its host along it) and, for a box
/// fold (a rectangular prism on a flat host), each depth (its centre panel is glued to both
/// pages along them) and the height (its end panels are glued to its sides along it). A step's
/// runs and a tent's feet meet their host in folds of their own, not glued ones.
bool thick_enough(const PrismHost& h, const Prism& m, double min_part)
{
    if (m.a1 - m.a0 < min_part)
        return false;
    if (m.kind != Prism::Kind::rectangular || !h.flat)
        return true;
    return std::min(m.s1, -m.s0) >= min_part && m.height >= min_part;
}

/// Grows a too thin prism to `min_part` where its host has room: along the hinge about its
/// middle, a box's depth and height. The score then judges the grown prism like any other (it
/// must still enclose no sample), so a thin slab inside a round model becomes a thin box.
void grow_to(const PrismHost& h, Prism& m, double min_part)
{
    if (m.a1 - m.a0 < min_part && h.length >= min_part) {
        const double mid =
            std::clamp(0.5 * (m.a0 + m.a1), 0.5 * min_part, h.length - 0.5 * min_part);
        m.a0 = mid - 0.5 * min_part;
        m.a1 = mid + 0.5 * min_part;
    }
    if (m.kind != Prism::Kind::rectangular || !h.flat)
        return;
    const double reach = std::min(h.across_max, -h.across_min);
    if (m.s1 < min_part && min_part <= reach) {
        m.s1 = min_part;
        m.s0 = -min_part;
    }
    if (m.height < min_part && min_part < h.up_max)
        m.height = min_part;
}

/// Keeps a prism inside what its host can carry and at least `min_part` thick; false if it
/// cannot.
bool fit_host(const PrismHost& h, Prism& m, double eps, double min_part)
{
    if (m.kind == Prism::Kind::rectangular) {
        if (h.flat) {
            // A box fold is centred on its host's hinge: equal depths (docs/DESIGN.md).
            const double reach = std::min(h.across_max, -h.across_min);
            double d = std::max(-m.s0, m.s1);
            if (d > reach + eps)
                return false;
            d = std::min(d, reach);
            m.s0 = -d;
            m.s1 = d;
        } else {
            m.s0 = 0;
            // A step must stay below its wall and on its page: one as tall as its wall (an
            // arm behind a box, flush with its top) stops just below it.
            if (m.height >= h.up_max * 0.98 && m.height <= h.up_max + eps)
                m.height = h.up_max * 0.98;
            if (m.s1 >= h.across_max || m.height > h.up_max * 0.98)
                return false;
        }
        if (m.s1 - m.s0 < eps || m.height < eps)
            return false;
    }
    m.a0 = std::max(m.a0, 0.0);
    m.a1 = std::min(m.a1, h.length);
    if (m.a1 - m.a0 <= eps)
        return false;
    grow_to(h, m, min_part);
    return thick_enough(h, m, min_part);
}

/// Grid cells of the localised sampling, one sorted list per level.
class Cells {
public:
    Cells(const std::vector<Vec3>& points, const std::vector<int>& remaining, double extent)
        : points_(points)
    {
        for (const Vec3& p : points)
            box_.extend(p);
        for (int level = 0; level < kLevels; ++level) {
            const double size = extent / double(2 << level);
            auto& list = levels_[level];
            list.reserve(remaining.size());
            for (int i : remaining)
                list.push_back({key(points[i], size), i});
            std::sort(list.begin(), list.end());
            sizes_[level] = size;
        }
    }
    /// A uniformly chosen sample in p's cell at `level` (may be p itself).
    int pick(int p, int level, std::mt19937_64& rng) const
    {
        const auto& list = levels_[level];
        const std::int64_t k = key(points_[p], sizes_[level]);
        auto lo = std::lower_bound(list.begin(), list.end(), std::make_pair(k, -1));
        auto hi = std::upper_bound(list.begin(), list.end(),
                                   std::make_pair(k, std::numeric_limits<int>::max()));
        const auto count = hi - lo;
        if (count <= 0)
            return p;
        std::uniform_int_distribution<long> d(0, long(count) - 1);
        return (lo + d(rng))->second;
    }

private:
    std::int64_t key(const Vec3& p, double size) const
    {
        const Vec3 q = (p - box_.min()) / size;
        const std::int64_t i = std::int64_t(q.x()), j = std::int64_t(q.y()),
                           k = std::int64_t(q.z());
        return (i * 4096 + j) * 4096 + k;
    }
    const std::vector<Vec3>& points_;
    Eigen::AlignedBox3d box_;
    std::array<std::vector<std::pair<std::int64_t, int>>, kLevels> levels_;
    std::array<double, kLevels> sizes_{};
};

/// True when a corner of the prism stands above the highest sample by more than ε: a prism
/// lies inside the model (a tent fitted to two near-parallel slopes would otherwise put its
/// apex far above it). Only the height: across and along, a box grown to the thinnest part
/// may reach past a thin model.
bool outside_model(const Prism& m, const PrismHost& h, const Eigen::AlignedBox3d& model, double eps)
{
    for (const Vec3& c : m.corners(h))
        if (c.z() > model.max().z() + eps)
            return true;
    return false;
}

struct Scored {
    Prism prism;
    double score = -1; ///< estimated inliers among the remaining samples
};

class Search {
public:
    Search(const SurfaceSamples& samples, const RansacOptions& o) : s_(samples), o_(o)
    {
        for (const Vec3& p : samples.points)
            box_.extend(p);
    }

    std::vector<Local> locals(const PrismHost& h) const
    {
        std::vector<Local> out(s_.points.size());
        for (size_t i = 0; i < out.size(); ++i)
            out[i] = to_local(h, s_.points[i], s_.normals[i]);
        return out;
    }

    /// Estimated inliers of m among `subset` (remaining samples above its host, in its host's
    /// coordinates, contiguous), or -1 when it encloses a sample of `guard` (all samples above
    /// the host) deeper than ε. Candidates not beating `to_beat` are not guarded (they cannot
    /// become the best): most draws stop after the subset.
    double score(const Prism& m, const std::vector<Local>& subset, const std::vector<Local>& guard,
                 bool flat, double scale, double to_beat) const
    {
        const Section sec = section_of(m);
        const double eps = o_.threshold;
        int n = 0;
        for (const Local& q : subset)
            n += classify(m, sec, q, eps, flat) == Where::face;
        if (n * scale <= to_beat)
            return -1;
        std::vector<const Local*> inside;
        for (const Local& q : guard)
            if (classify(m, sec, q, eps, flat) == Where::inside)
                inside.push_back(&q);
        if (inside.size() > 1 && m.kind == Prism::Kind::rectangular && flat) {
            // A box fold stands on its page: under a model that floats on legs or wheels (a
            // truck's chassis) it fills the room below the model's underside. What it encloses
            // there is the legs' side, not the model's inside, as long as the underside lies in
            // the box's lower half (docs/DESIGN.md, "Boxes under a raised model").
            double floor = -1e300;
            for (const Local* q : inside)
                if (q->nt < -kNormalAgreement)
                    floor = std::max(floor, q->t);
            if (floor > 0 && floor <= 0.5 * m.height)
                inside.erase(std::remove_if(inside.begin(), inside.end(),
                                            [&](const Local* q) { return q->t <= floor + eps; }),
                             inside.end());
        }
        if (inside.size() > 1)
            return -1;
        return n * scale;
    }

    /// Grows the prism along the hinge over the samples that carry its top, sides or slopes
    /// without a gap wider than `gap`: two or four points fix the section, not the length.
    void extend_along(Prism& m, const std::vector<Local>& subset, double gap,
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

    /// Local optimisation: each face moves to the median of its inliers, slopes to their
    /// least-squares lines.
    void refit(Prism& m, const std::vector<Local>& l, const std::vector<int>& subset,
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

private:
    const SurfaceSamples& s_;
    const RansacOptions& o_;
    Eigen::AlignedBox3d box_; ///< the samples' bounding box (card frame)
};

/// True when the prism's box overlaps one of `taken` by more than ε along every axis: two
/// primitives may touch (one stands on the other) but not share volume, or their mechanisms
/// would.
bool overlaps(const Prism& m, const PrismHost& h, const std::vector<Eigen::AlignedBox3d>& taken,
              double eps)
{
    Eigen::AlignedBox3d box;
    for (const Vec3& c : m.corners(h))
        box.extend(c);
    for (const auto& t : taken) {
        const Vec3 lo = box.min().cwiseMax(t.min()), hi = box.max().cwiseMin(t.max());
        if (((hi - lo).array() > eps).all())
            return true;
    }
    return false;
}

std::vector<int> every_kth(const std::vector<int>& from, size_t at_most)
{
    const size_t k = std::max<size_t>(1, from.size() / std::max<size_t>(1, at_most));
    std::vector<int> out;
    for (size_t i = 0; i < from.size(); i += k)
        out.push_back(from[i]);
    return out;
}

/// The pairs a box offers (mirrors build_parallel_box: top over its middle, a side and the page
/// beyond it on each side).
void offer_box_pairs(const Prism& m, int index, std::vector<PrismHost>& hosts)
{
    const PrismHost h = hosts[m.host];
    const std::string name = "P" + std::to_string(index + 1);
    const Vec3 start = h.origin + m.a0 * h.axis;
    const double d = m.s1;
    PrismHost top;
    top.name = name + ".top";
    top.parent = index;
    top.part = "top";
    top.origin = start + m.height * h.up;
    top.axis = h.axis;
    top.across = h.across;
    top.up = h.up;
    top.length = m.a1 - m.a0;
    top.across_min = -d;
    top.across_max = d;
    hosts.push_back(top);
    for (int side = 0; side < 2; ++side) {
        PrismHost p;
        p.parent = index;
        p.part = side == 0 ? "side_ground" : "side_backdrop";
        p.name = name + "." + p.part;
        p.flat = false;
        p.axis = h.axis;
        p.across = side == 0 ? h.across : Vec3(-h.across);
        p.up = h.up;
        p.origin = start + d * p.across;
        p.length = m.a1 - m.a0;
        p.across_max = side == 0 ? h.across_max - d : -h.across_min - d;
        p.up_max = m.height;
        if (p.across_max > 0)
            hosts.push_back(p);
    }
}

} // namespace

double draw_probability(double n, double N, int k, int hosts, int levels)
{
    if (N <= 0)
        return 1.0;
    // Of the minimal samples inside a shape, about a quarter generate it: a box needs one point
    // on its top and one on a side, a triangular prism two on each slope (docs/MATH.md).
    constexpr double generating = 0.25;
    return std::min(1.0, generating * n /
                             (N * std::max(hosts, 1) * std::max(levels, 1) * std::pow(2.0, k - 1)));
}

double found_probability(double n, double N, int k, int hosts, int levels, long draws)
{
    const double p = draw_probability(n, N, k, hosts, levels);
    if (p >= 1.0)
        return 1.0;
    return 1.0 - std::exp(double(draws) * std::log1p(-p));
}

std::vector<Vec3> Prism::corners(const PrismHost& h) const
{
    auto at = [&](double a, double s, double t) {
        return Vec3(h.origin + a * h.axis + s * h.across + t * h.up);
    };
    std::vector<Vec3> c;
    if (kind == Kind::rectangular) {
        for (double t : {0.0, height})
            for (double a : {a0, a1})
                for (double s : {s0, s1})
                    c.push_back(at(a, s, t));
    } else {
        for (double a : {a0, a1}) {
            c.push_back(at(a, s0, 0));
            c.push_back(at(a, s1, 0));
            c.push_back(at(a, apex_s, height));
        }
    }
    return c;
}

RansacResult fit_prisms(const SurfaceSamples& samples, const PrismHost& card,
                        const RansacOptions& o)
{
    RansacResult r;
    const size_t total = samples.points.size();
    r.hosts.push_back(card);
    r.owner.assign(total, -1);
    r.on_base.assign(total, false);
    r.on_principal.assign(total, false);
    if (total == 0)
        return r;
    Search search(samples, o);
    std::vector<std::vector<Local>> locals{search.locals(card)};
    const double eps = o.threshold;
    // Samples on a host's plane facing it (the model's base on the card, a box standing on
    // another's top) are the paper itself: no prism needs to explain them.
    auto mark_base = [&](int host) {
        const PrismHost& h = r.hosts[host];
        for (size_t i = 0; i < total; ++i) {
            const Local& l = locals[host][i];
            if (l.a < -eps || l.a > h.length + eps)
                continue;
            const bool on_page = std::abs(l.t) < eps && l.nt < -kNormalAgreement &&
                                 l.s > h.across_min - eps && l.s < h.across_max + eps;
            // A right-angle pair's wall too: a part built against a box's side.
            const bool on_wall = !h.flat && std::abs(l.s) < eps && l.ns < -kNormalAgreement &&
                                 l.t > -eps && l.t < h.up_max + eps;
            if (on_page || on_wall)
                r.on_base[i] = true;
        }
    };
    mark_base(0);

    Eigen::AlignedBox3d box;
    for (const Vec3& p : samples.points)
        box.extend(p);
    const double extent = box.sizes().maxCoeff();
    std::mt19937_64 rng(o.seed);
    std::vector<int> all(total);
    for (size_t i = 0; i < total; ++i)
        all[i] = int(i);
    const std::vector<int> guard = every_kth(all, 3000);
    std::vector<Eigen::AlignedBox3d> taken; // boxes of the accepted prisms, card frame

    while (int(r.prisms.size()) < o.max_primitives) {
        stop_if_cancelled(o.cancel, "fit_design: fitting primitives");
        std::vector<int> remaining;
        for (size_t i = 0; i < total; ++i)
            if (r.owner[i] < 0 && !r.on_base[i])
                remaining.push_back(int(i));
        const double N = double(remaining.size());
        if (N < o.min_points) {
            r.stopped_by_probability = true;
            break;
        }
        const std::vector<int> subset = every_kth(remaining, 1000);
        const double scale = N / double(subset.size());
        // Gap allowed along the hinge between samples of one face: a few sample spacings of
        // the scoring subset.
        const double gap = 4.0 * samples.spacing * std::sqrt(scale);
        Cells cells(samples.points, remaining, extent);
        const int H = int(r.hosts.size());
        // A draw picks its host among those its first sample stands on: at most this many.
        int hosts_per_sample = 1;
        for (int i : remaining) {
            int count = 0;
            for (int h = 0; h < H; ++h)
                count += above_host(r.hosts[h], locals[h][i], eps);
            hosts_per_sample = std::max(hosts_per_sample, count);
        }
        // Per host, the scoring subset and the guard above it, contiguous in its coordinates.
        std::vector<std::vector<Local>> sub(H), grd(H);
        for (int h = 0; h < H; ++h) {
            for (int i : subset)
                if (above_host(r.hosts[h], locals[h][i], eps))
                    sub[h].push_back(locals[h][i]);
            for (int i : guard)
                if (above_host(r.hosts[h], locals[h][i], eps))
                    grd[h].push_back(locals[h][i]);
        }
        std::uniform_int_distribution<size_t> pick_point(0, remaining.size() - 1);
        std::uniform_int_distribution<int> pick_level(0, kLevels - 1);

        Scored best_rect, best_tri;
        long draws = 0, tri_draws = 0;
        bool accepted = false;
        while (!accepted) {
            for (int batch = 0; batch < 64; ++batch, ++draws) {
                const int p1 = remaining[pick_point(rng)];
                std::vector<int> eligible;
                for (int h = 0; h < H; ++h)
                    if (above_host(r.hosts[h], locals[h][p1], eps))
                        eligible.push_back(h);
                const int level = pick_level(rng);
                const int p2 = cells.pick(p1, level, rng);
                const int p3 = cells.pick(p1, level, rng);
                const int p4 = cells.pick(p1, level, rng);
                if (eligible.empty())
                    continue;
                std::uniform_int_distribution<size_t> pick_host(0, eligible.size() - 1);
                const int h = eligible[pick_host(rng)];
                const PrismHost& host = r.hosts[h];
                const auto& l = locals[h];
                if (!above_host(host, l[p2], eps))
                    continue;
                // Rectangular: two points fix the top and the sides (Fig 5.4).
                Prism rect;
                rect.kind = Prism::Kind::rectangular;
                rect.host = h;
                rect.height = std::max(l[p1].t, l[p2].t);
                rect.s1 = host.flat ? std::max(std::abs(l[p1].s), std::abs(l[p2].s))
                                    : std::max(l[p1].s, l[p2].s);
                rect.s0 = host.flat ? -rect.s1 : 0.0;
                rect.a0 = std::min(l[p1].a, l[p2].a);
                rect.a1 = std::max(l[p1].a, l[p2].a);
                if (fit_host(host, rect, eps, o.min_part)) {
                    search.extend_along(rect, sub[h], gap, host);
                    if (fit_host(host, rect, eps, o.min_part)) {
                        const double sc =
                            search.score(rect, sub[h], grd[h], host.flat, scale, best_rect.score);
                        if (sc > best_rect.score && !overlaps(rect, host, taken, eps) &&
                            !outside_model(rect, host, box, eps))
                            best_rect = {rect, sc};
                    }
                }
                // Triangular: two points on each slope (Fig 5.4), flat hosts only.
                if (!host.flat || !above_host(host, l[p3], eps) || !above_host(host, l[p4], eps))
                    continue;
                ++tri_draws;
                const Vec2 q1(l[p1].s, l[p1].t), q2(l[p2].s, l[p2].t), q3(l[p3].s, l[p3].t),
                    q4(l[p4].s, l[p4].t);
                if ((q2 - q1).norm() < eps || (q4 - q3).norm() < eps)
                    continue;
                Prism tri;
                tri.kind = Prism::Kind::triangular;
                tri.host = h;
                if (!triangle_from_lines(host, q1, (q2 - q1).normalized(), q3,
                                         (q4 - q3).normalized(), eps, tri))
                    continue;
                tri.a0 = std::min({l[p1].a, l[p2].a, l[p3].a, l[p4].a});
                tri.a1 = std::max({l[p1].a, l[p2].a, l[p3].a, l[p4].a});
                if (!fit_host(host, tri, eps, o.min_part))
                    continue;
                search.extend_along(tri, sub[h], gap, host);
                if (!fit_host(host, tri, eps, o.min_part))
                    continue;
                const double sc = search.score(tri, sub[h], grd[h], true, scale, best_tri.score);
                if (sc > best_tri.score && !overlaps(tri, host, taken, eps) &&
                    !outside_model(tri, host, box, eps))
                    best_tri = {tri, sc};
            }
            r.draws += 64;
            stop_if_cancelled(o.cancel, "fit_design: fitting primitives");
            // Algorithm 5.2: keep the best candidate once a larger one would have been drawn
            // with probability p_t; stop when even a τ-sized one would have been.
            const bool rect_better = best_rect.score >= best_tri.score;
            const Scored& best = rect_better ? best_rect : best_tri;
            const int k = rect_better ? 2 : 4;
            const long s = rect_better ? draws : tri_draws;
            if (best.score >= o.min_points &&
                found_probability(best.score, N, k, hosts_per_sample, kLevels, s) > o.probability) {
                Prism m = best.prism;
                const PrismHost& host = r.hosts[m.host];
                search.refit(m, locals[m.host], remaining, host);
                const Section sec = section_of(m);
                int n = 0;
                for (int i : remaining) {
                    int face = -1;
                    if (classify(m, sec, locals[m.host][i], eps, host.flat, &face) == Where::face) {
                        r.owner[i] = int(r.prisms.size());
                        r.on_principal[i] = face <= 2 || face == 5;
                        ++n;
                    }
                }
                m.inliers = n;
                r.prisms.push_back(m);
                Eigen::AlignedBox3d box;
                for (const Vec3& c : m.corners(host))
                    box.extend(c);
                taken.push_back(box);
                if (m.kind == Prism::Kind::rectangular && host.flat) {
                    const size_t before = r.hosts.size();
                    offer_box_pairs(m, int(r.prisms.size()) - 1, r.hosts);
                    for (size_t h = before; h < r.hosts.size(); ++h) {
                        locals.push_back(search.locals(r.hosts[h]));
                        mark_base(int(h));
                    }
                }
                accepted = true;
            } else if (found_probability(o.min_points, N, 2, hosts_per_sample, kLevels, draws) >
                           o.probability &&
                       found_probability(o.min_points, N, 4, hosts_per_sample, kLevels, tri_draws) >
                           o.probability) {
                r.stopped_by_probability = true;
                return r;
            } else if (r.draws >= o.max_draws) {
                return r;
            }
        }
    }
    return r;
}

} // namespace popup
