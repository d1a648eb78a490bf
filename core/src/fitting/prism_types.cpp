#include "popup/fitting/prism_types.hpp"

namespace popup {

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

} // namespace popup
