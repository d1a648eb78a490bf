#include "localised_sampling.hpp"

#include <algorithm>
#include <limits>

namespace popup::prism_search {

Cells::Cells(const std::vector<Vec3>& points, const std::vector<int>& remaining, double extent)
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
        // Each listed sample's cell as a run of the list: a pick needs no search.
        auto& runs = runs_[level];
        runs.assign(points.size(), {0, 0});
        for (size_t b = 0; b < list.size();) {
            size_t e = b + 1;
            while (e < list.size() && list[e].first == list[b].first)
                ++e;
            for (size_t k = b; k < e; ++k)
                runs[size_t(list[k].second)] = {int(b), int(e)};
            b = e;
        }
    }
}

int Cells::pick(int p, int level, std::mt19937_64& rng) const
{
    const auto& list = levels_[level];
    const auto [b, e] = runs_[level][size_t(p)];
    if (e > b) {
        std::uniform_int_distribution<long> d(0, long(e - b) - 1);
        return list[size_t(b + d(rng))].second;
    }
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

std::int64_t Cells::key(const Vec3& p, double size) const
{
    const Vec3 q = (p - box_.min()) / size;
    const std::int64_t i = std::int64_t(q.x()), j = std::int64_t(q.y()), k = std::int64_t(q.z());
    return (i * 4096 + j) * 4096 + k;
}

std::vector<int> every_kth(const std::vector<int>& from, size_t at_most)
{
    const size_t k = std::max<size_t>(1, from.size() / std::max<size_t>(1, at_most));
    std::vector<int> out;
    for (size_t i = 0; i < from.size(); i += k)
        out.push_back(from[i]);
    return out;
}

} // namespace popup::prism_search
