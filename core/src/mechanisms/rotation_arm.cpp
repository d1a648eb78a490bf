#include "popup/mechanisms/rotation_arm.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "mechanism_builder.hpp"

namespace popup {

RotationArmPoints rotation_arm_points(const RotationArmParams& p, double opening)
{
    // The spine tip R = l (cos t, sin t) in the (y, z) plane with tan(t/2) = w cos δ / l,
    // S = (w sin δ, l, w cos δ) and its mirror S', and P = R + (h / w)(R − S); δ = φ/2
    // (docs/MATH.md, Rotation).
    const double l = p.spine, w = p.run, h = p.arm, d = opening / 2;
    const double t = 2 * std::atan2(w * std::cos(d), l);
    RotationArmPoints a;
    a.R = Vec3(0, l * std::cos(t), l * std::sin(t));
    a.S = Vec3(w * std::sin(d), l, w * std::cos(d));
    a.Sb = Vec3(-w * std::sin(d), l, w * std::cos(d));
    a.P = a.R + (h / w) * (a.R - a.S);
    return a;
}

Vec3 rotation_arm_tip(const RotationArmParams& p, double opening)
{
    const Vec3 P = rotation_arm_points(p, opening).P;
    return {P.x(), p.offset + P.y(), P.z()};
}

Vec3 rotation_arm_tip_on_layer_side(const RotationArmParams& arm, const FloatingLayerParams& layer,
                                    LayerSide side, double angle)
{
    const BasePatchPair pair = floating_layer_side(layer, side, angle);
    const Vec3 tip = rotation_arm_tip(arm, pair.opening);
    return pair.to_world(tip.x(), tip.y(), tip.z());
}

Result<MechanismParts> add_rotation_arm(Scaffold& scaffold, const BasePatchPair& host,
                                        const RotationArmParams& p, const std::string& name)
{
    Result<MechanismParts> r;
    Diagnostics& e = r.diagnostics;
    if (!(host.opening > 1e-9 && host.opening <= M_PI + 1e-9)) {
        std::ostringstream m;
        m << name << ": host " << host.name << " is open " << host.opening * 180 / M_PI
          << "° at the design state; a rotation arm needs a host open more than 0° and at most "
             "180°";
        e.push_back(Diagnostic::error(DiagnosticCode::bad_host, m.str(), about_parameter("Host")));
    }
    // A host's length is a difference of coordinates (a layer from offset to offset + width):
    // a spine as long as it may exceed it by rounding.
    const double length = host.length * (1 + 1e-12);
    if (!(p.spine > 0 && p.spine <= length)) {
        std::ostringstream m;
        m << "> 0 and <= " << host.length << " mm (the length of " << host.name << ")";
        range_error(e, name, "Spine", p.spine, "mm", m.str());
    } else if (!(p.offset >= 0 && p.offset + p.spine <= length)) {
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
    // Flat on a flat host (P = (−h, l, 0)); on a host open less, the popped branch of the same
    // closed form at the host's design opening, which the simulator then follows.
    const double l = p.spine, y0 = p.offset;
    const bool flat = std::abs(host.opening - M_PI) <= 1e-9;
    RotationArmPoints a = rotation_arm_points(p, flat ? M_PI : host.opening);
    if (flat) {
        // Exactly on the host, not through cos(π/2) ≈ 6e-17.
        a.R = Vec3(0, l, 0);
        a.S = Vec3(p.run, l, 0);
        a.Sb = Vec3(-p.run, l, 0);
        a.P = Vec3(-p.arm, l, 0);
    }
    const Vec3 base(0, y0, 0);
    const Vec3 O = base, R = base + a.R, S = base + a.S, Sb = base + a.Sb, P = base + a.P;
    MechanismBuilder m(scaffold, host, name);
    // Flat, both wings lie on the host printed side up; R sits on the ground wing's edge S-P.
    const int wing = m.patch({O, S, P}, PatchRole::support, "wing_arm");
    const int other = m.patch({O, R, Sb}, PatchRole::support, "wing_backdrop");
    m.tab(host.ground, wing, O, S, FoldDirection::valley);
    m.tab(host.backdrop, other, O, Sb, FoldDirection::valley);
    // The spine rises off the host, so the backdrop wing turns away from the arm wing's printed
    // side: a mountain (the sign of det[S, R, S'] in docs/MATH.md, Rotation). The spine crosses
    // the arm wing's paper, so the backdrop wing is a sheet of its own, glued on along it.
    m.tab(wing, other, O, R, FoldDirection::mountain);
    double lo = std::min(0.0, a.P.y()), hi = std::max(l, a.P.y());
    for (int k = 0; k <= 90; ++k) {
        const double y = rotation_arm_tip(p, host.opening * k / 90).y() - y0;
        lo = std::min(lo, y);
        hi = std::max(hi, y);
    }
    m.sweeps(y0 + lo, y0 + hi);
    return m.finish();
}

} // namespace popup
