#pragma once
// Internal: closed loops with an R-tree over their edges (Boost.Geometry), so that inside tests
// and boundary distances cost O(log n) per query instead of O(n): outlines from models have
// tens of thousands of vertices.
#include <array>
#include <memory>
#include <vector>

#include "popup/geometry/vectors.hpp"

namespace popup {

class IndexedLoops {
public:
    explicit IndexedLoops(const std::vector<Loop2>& loops);
    ~IndexedLoops();
    IndexedLoops(IndexedLoops&&) noexcept;
    IndexedLoops& operator=(IndexedLoops&&) noexcept;

    /// Even-odd inside test over all loops together (the same rule as point_in_polygon).
    bool contains(const Vec2& q) const;
    /// Distance from q to the nearest edge of any loop.
    double distance_to_boundary(const Vec2& q) const;

private:
    struct Tree;
    std::vector<std::array<Vec2, 2>> edges_;
    std::unique_ptr<Tree> tree_;
};

} // namespace popup
