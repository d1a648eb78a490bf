#pragma once
// Internal: the localised sampling of the primitive search (Schnabel et al. 2007): grid cells
// of several sizes from which a minimal sample's further points are drawn near its first.
#include <array>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "popup/geometry/pose.hpp"

namespace popup::prism_search {

constexpr int kLevels = 5; ///< cell sizes of the localised sampling

/// Grid cells of the localised sampling, one sorted list per level.
class Cells {
public:
    Cells(const std::vector<Vec3>& points, const std::vector<int>& remaining, double extent);
    /// A uniformly chosen sample in p's cell at `level` (may be p itself).
    int pick(int p, int level, std::mt19937_64& rng) const;

private:
    std::int64_t key(const Vec3& p, double size) const;
    const std::vector<Vec3>& points_;
    Eigen::AlignedBox3d box_;
    std::array<std::vector<std::pair<std::int64_t, int>>, kLevels> levels_;
    std::array<double, kLevels> sizes_{};
    /// Per level and sample, its cell's run [first, past the last) of the list; empty for a
    /// sample not listed.
    std::array<std::vector<std::pair<int, int>>, kLevels> runs_;
};

/// At most about `at_most` of `from`, every k-th in order.
std::vector<int> every_kth(const std::vector<int>& from, size_t at_most);

} // namespace popup::prism_search
