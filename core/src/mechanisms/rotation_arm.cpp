#include "popup/mechanisms/rotation_arm.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "mechanism_builder.hpp"

namespace popup {

Vec3 rotation_arm_tip(const RotationArmParams& p, double opening)
{
    // The spine tip R = l (cos t, sin t) in the (y, z) plane with tan(t/2) = w cos δ / l, and
    // P = R + (h / w)(R − S), S = (w sin δ, l, w cos δ) (docs/MATH.md, Rotation).
    const double l = p.spine, w = p.run, h = p.arm, d = opening / 2;
    const double t = 2 * std::atan2(w * std::cos(d), l);
    const Vec3 R(0, l * std::cos(t), l * std::sin(t));
    const Vec3 S(w * std::sin(d), l, w * std::cos(d));
    const Vec3 P = R + (h / w) * (R - S);
    return {P.x(), p.offset + P.y(), P.z()};
}

Result<MechanismParts> add_rotation_arm(Scaffold& scaffold, const BasePatchPair& host,
                                        const RotationArmParams& p, const std::string& name)
{
    Result<MechanismParts> r;
    Diagnostics& e = r.diagnostics;
    check_flat_host(name, host, "a rotation arm", e);
    if (!(p.spine > 0 && p.spine <= host.length)) {
        std::ostringstream m;
        m << "> 0 and <= " << host.length << " mm (the length of " << host.name << ")";
        range_error(e, name, "Spine", p.spine, "mm", m.str());
    } else if (!(p.offset >= 0 && p.offset + p.spine <= host.length)) {
        // The spine fits: only Offset can be at fault, and its range exists.
        std::ostringstream m;
        m << ">= 0 and <= " << host.length - p.spine << " mm (" << host.name << " is "
          << host.length << " mm long, the spine " << p.spine << " mm)";
        range_error(e, name, "Offset", p.offset, "mm", m.str());
    }
    check_run(e, name, "Run", p.run, std::min(host.ground_depth, host.backdrop_depth),
              "ground and backdrop");
    if (e.empty()) {
        const double longest = p.spine * p.spine / p.run;
        const double room = std::min(longest, host.backdrop_depth);
        if (!(p.arm > 0 && p.arm <= room)) {
            std::ostringstream m;
            m << "> 0 and <= " << room << " mm (Spine²/Run keeps the arm above the backdrop; "
              << "the backdrop is " << host.backdrop_depth << " mm deep)";
            range_error(e, name, "Arm", p.arm, "mm", m.str());
        }
    }
    if (e.empty())
        check_part_sizes(scaffold, name, {{"Spine", p.spine}, {"Run", p.run}, {"Arm", p.arm}}, e);
    if (!e.empty()) {
        r.ok = false;
        return r;
    }
    const double l = p.spine, w = p.run, y0 = p.offset;
    const Vec3 O(0, y0, 0), R(0, y0 + l, 0), S(w, y0 + l, 0), Sb(-w, y0 + l, 0),
        P(-p.arm, y0 + l, 0);
    MechanismBuilder m(scaffold, host, name);
    // Both wings lie on the host, printed side up; R sits on the ground wing's edge S-P.
    const int wing = m.patch({O, S, P}, PatchRole::support, "wing_arm");
    const int other = m.patch({O, R, Sb}, PatchRole::support, "wing_backdrop");
    m.tab(host.ground, wing, O, S, FoldDirection::valley);
    m.tab(host.backdrop, other, O, Sb, FoldDirection::valley);
    // The spine rises off the host, so the backdrop wing turns away from the arm wing's printed
    // side: a mountain (the sign of det[S, R, S'] in docs/MATH.md, Rotation). The spine crosses
    // the arm wing's paper, so the backdrop wing is a sheet of its own, glued on along it.
    m.tab(wing, other, O, R, FoldDirection::mountain);
    double lo = 0.0, hi = l;
    for (int k = 0; k <= 90; ++k) {
        const double y = rotation_arm_tip(p, M_PI * k / 90).y() - y0;
        lo = std::min(lo, y);
        hi = std::max(hi, y);
    }
    m.sweeps(y0 + lo, y0 + hi);
    return m.finish();
}

} // namespace popup
