#include "reach_floor.hpp"

#include <algorithm>
#include <cmath>

namespace popup::motion {

double card_reach(const CardParams& card, double theta)
{
    return card.depth * std::sin(theta / 2);
}

double reach_floor_mm(const ChainTarget& t, const CardParams& card)
{
    if (t.s.empty())
        return 0.0;
    double sum = 0.0;
    for (std::size_t k = 0; k < t.s.size(); ++k) {
        const double beyond =
            std::max(0.0, std::abs(t.target[k].x()) - card_reach(card, M_PI * t.s[k]));
        sum += beyond * beyond;
    }
    return std::sqrt(sum / double(t.s.size()));
}

} // namespace popup::motion
