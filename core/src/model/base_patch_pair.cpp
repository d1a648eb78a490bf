#include "popup/model/base_patch_pair.hpp"

#include <cmath>

namespace popup {

Vec2 BasePatchPair::ground_direction() const
{
    return {std::sin(opening / 2), std::cos(opening / 2)};
}

Vec2 BasePatchPair::backdrop_direction() const
{
    return {-std::sin(opening / 2), std::cos(opening / 2)};
}

Vec3 BasePatchPair::on_base(double r, double y) const
{
    const Vec2 d = r >= 0 ? ground_direction() : backdrop_direction();
    const double s = std::abs(r);
    return to_world(s * d.x(), y, s * d.y());
}

} // namespace popup
