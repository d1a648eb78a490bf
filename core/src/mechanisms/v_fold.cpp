#include "popup/mechanisms/v_fold.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "mechanism_builder.hpp"

namespace popup {

Result<MechanismParts> add_v_fold(Scaffold& scaffold, const BasePatchPair& host,
                                  const VFoldParams& p, const std::string& name)
{
    Result<MechanismParts> r;
    Diagnostics& e = r.diagnostics;
    const double deg = 180.0 / M_PI;
    if (!(p.hinge_angle > 0 && p.hinge_angle < M_PI / 2))
        range_error(e, name, "HingeAngle", p.hinge_angle * deg, "°", "> 0° and < 90°");
    if (!(p.spine_angle > 0 && p.spine_angle < M_PI))
        range_error(e, name, "SpineAngle", p.spine_angle * deg, "°", "> 0° and < 180°");
    const double longest = std::max({host.length, host.ground_depth, host.backdrop_depth});
    if (!(p.spine > 0 && p.spine <= longest)) {
        std::ostringstream m;
        m << "> 0 and <= " << longest << " mm (the host's largest extent)";
        range_error(e, name, "Spine", p.spine, "mm", m.str());
    }
    if (e.empty()) {
        const double reach = p.run * std::sin(p.hinge_angle);
        std::ostringstream m;
        m << "> 0 mm and reach at most " << std::min(host.ground_depth, host.backdrop_depth)
          << " mm from the host's hinge (Run·sin HingeAngle)";
        if (!(p.run > 0 && reach < std::min(host.ground_depth, host.backdrop_depth)))
            range_error(e, name, "Run", p.run, "mm", m.str());
    }
    if (e.empty()) {
        // Extent along the host hinge: from O to the farthest of A, B and P.
        const double lo =
            std::min({0.0, p.run * std::cos(p.hinge_angle), p.spine * std::cos(p.spine_angle)});
        const double hi =
            std::max({0.0, p.run * std::cos(p.hinge_angle), p.spine * std::cos(p.spine_angle)});
        std::ostringstream m;
        m << ">= " << -lo << " mm and <= " << host.length - hi << " mm (the v-fold spans "
          << hi - lo << " mm of " << host.name << ")";
        if (!(p.offset + lo >= 0 && p.offset + hi <= host.length))
            range_error(e, name, "Offset", p.offset, "mm", m.str());
    }
    if (!e.empty()) {
        r.ok = false;
        return r;
    }
    const double s = p.run * std::sin(p.hinge_angle), along = p.run * std::cos(p.hinge_angle);
    const Vec2 g = host.ground_direction(), b = host.backdrop_direction();
    const Vec3 O(0, p.offset, 0);
    const Vec3 A(s * g.x(), p.offset + along, s * g.y());
    const Vec3 B(s * b.x(), p.offset + along, s * b.y());
    const Vec3 P(0, p.offset + p.spine * std::cos(p.spine_angle),
                 p.spine * std::sin(p.spine_angle));
    MechanismBuilder m(scaffold, host, name);
    const int wing_g = m.patch({O, A, P}, PatchRole::support, "wing_ground");
    const int wing_b = m.patch({O, P, B}, PatchRole::support, "wing_backdrop");
    m.hinge(host.ground, wing_g, O, A);
    m.hinge(host.backdrop, wing_b, O, B);
    m.hinge(wing_g, wing_b, O, P);
    r.value = m.finish();
    return r;
}

} // namespace popup
