#include "indexed_loops.hpp"

#include <array>
#include <limits>

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

#include "polygon_2d.hpp"

namespace popup {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BoostPoint = bg::model::point<double, 2, bg::cs::cartesian>;
using BoostBox = bg::model::box<BoostPoint>;
using Entry = std::pair<BoostBox, size_t>;

struct IndexedLoops::Tree {
    bgi::rtree<Entry, bgi::rstar<16>> rtree;
    // Horizontal edges never count as crossings of a horizontal ray, yet a ray along one would
    // meet all of them: inside tests use the other edges only.
    bgi::rtree<Entry, bgi::rstar<16>> sloped;
};

IndexedLoops::IndexedLoops(const std::vector<Loop2>& loops) : tree_(std::make_unique<Tree>())
{
    std::vector<Entry> entries;
    for (const Loop2& loop : loops)
        for (size_t i = 0; i < loop.size(); ++i) {
            const Vec2& a = loop[i];
            const Vec2& b = loop[(i + 1) % loop.size()];
            entries.push_back({BoostBox(BoostPoint(std::min(a.x(), b.x()), std::min(a.y(), b.y())),
                                        BoostPoint(std::max(a.x(), b.x()), std::max(a.y(), b.y()))),
                               edges_.size()});
            edges_.push_back({a, b});
        }
    tree_->rtree = bgi::rtree<Entry, bgi::rstar<16>>(entries); // bulk loading: O(n log n)
    std::vector<Entry> sloped;
    for (const Entry& e : entries)
        if (edges_[e.second][0].y() != edges_[e.second][1].y())
            sloped.push_back(e);
    tree_->sloped = bgi::rtree<Entry, bgi::rstar<16>>(sloped);
}

IndexedLoops::~IndexedLoops() = default;
IndexedLoops::IndexedLoops(IndexedLoops&&) noexcept = default;
IndexedLoops& IndexedLoops::operator=(IndexedLoops&&) noexcept = default;

bool IndexedLoops::contains(const Vec2& q) const
{
    // Crossings of the ray from q toward +x, counted with point_in_polygon's half-open rule.
    const BoostBox ray(BoostPoint(q.x(), q.y()),
                       BoostPoint(std::numeric_limits<double>::max(), q.y()));
    bool inside = false;
    for (auto it = tree_->sloped.qbegin(bgi::intersects(ray)); it != tree_->sloped.qend(); ++it) {
        const Vec2& a = edges_[it->second][0];
        const Vec2& b = edges_[it->second][1];
        if ((a.y() > q.y()) != (b.y() > q.y()) &&
            q.x() < (b.x() - a.x()) * (q.y() - a.y()) / (b.y() - a.y()) + a.x())
            inside = !inside;
    }
    return inside;
}

double IndexedLoops::distance_to_boundary(const Vec2& q) const
{
    // An edge within distance r of q has its box within r too: search a growing square until
    // the nearest edge found lies inside the searched radius.
    if (edges_.empty())
        return std::numeric_limits<double>::infinity();
    const BoostBox all = tree_->rtree.bounds();
    double r = 1e-3 * std::max(1.0, bg::distance(all.min_corner(), all.max_corner()));
    for (;;) {
        const BoostBox square(BoostPoint(q.x() - r, q.y() - r), BoostPoint(q.x() + r, q.y() + r));
        double best = std::numeric_limits<double>::infinity();
        for (auto it = tree_->rtree.qbegin(bgi::intersects(square)); it != tree_->rtree.qend();
             ++it)
            best = std::min(best,
                            distance_to_segment(q, edges_[it->second][0], edges_[it->second][1]));
        if (best <= r)
            return best;
        r *= 4.0;
    }
}

} // namespace popup
