#include "popup/mechanisms/v_fold.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "mechanism_builder.hpp"

namespace popup {

Vec3 v_fold_tip(const VFoldParams& p, double design_opening, double opening)
{
    // P = (0, p_y, p_z) on |P| = L and |P − A(φ)| = |P0 − A(φ_d)|: a line meets a circle
    // (docs/MATH.md, V-fold); the root is the one the design state sits on.
    const double X = p.run * std::sin(p.hinge_angle), Y = p.run * std::cos(p.hinge_angle);
    const double L = p.spine;
    const Vec2 p0(L * std::cos(p.spine_angle), L * std::sin(p.spine_angle));
    auto roots = [&](double phi, Vec2& plus, Vec2& minus) {
        const double c = X * std::cos(phi / 2);
        // K = p_y·Y + p_z·X cos(φ/2) is the same at every φ: take it at the design state.
        const double K = Y * p0.x() + X * std::cos(design_opening / 2) * p0.y();
        const double n2 = Y * Y + c * c;
        const double disc = std::sqrt(std::max(0.0, n2 * L * L - K * K));
        plus = Vec2(K * Y - c * disc, K * c + Y * disc) / n2;
        minus = Vec2(K * Y + c * disc, K * c - Y * disc) / n2;
    };
    Vec2 plus, minus;
    roots(design_opening, plus, minus);
    const bool take_plus = (plus - p0).norm() <= (minus - p0).norm();
    roots(opening, plus, minus);
    const Vec2 tip = take_plus ? plus : minus;
    return {0.0, p.offset + tip.x(), tip.y()};
}

BasePatchPair v_fold_wings(const VFoldParams& p, double design_opening, double opening)
{
    const double X = p.run * std::sin(p.hinge_angle), Y = p.run * std::cos(p.hinge_angle);
    const double s = std::sin(opening / 2), c = std::cos(opening / 2);
    const Vec3 O(0, p.offset, 0), A(X * s, p.offset + Y, X * c), B(-X * s, p.offset + Y, X * c);
    const Vec3 P = v_fold_tip(p, design_opening, opening);
    BasePatchPair wings;
    wings.origin = O;
    wings.axis = (P - O).normalized();
    auto across = [&](const Vec3& x) {
        const Vec3 d = x - O;
        return Vec3(d - d.dot(wings.axis) * wings.axis);
    };
    const Vec3 a = across(A), b = across(B);
    const Vec3 dg = a.normalized(), db = b.normalized();
    wings.up = (dg + db).normalized();
    wings.opening = std::acos(std::clamp(dg.dot(db), -1.0, 1.0));
    wings.length = (P - O).norm();
    const bool ground_wing_on_x = wings.x_axis().dot(dg) > 0;
    wings.ground_depth = (ground_wing_on_x ? a : b).norm();
    wings.backdrop_depth = (ground_wing_on_x ? b : a).norm();
    return wings;
}

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
        if (hi - lo > host.length) {
            // No Offset can help: name the part that makes the v-fold too long, with its bound
            // (Run·cos HingeAngle and Spine·cos SpineAngle add up when they point opposite ways).
            const double rc = p.run * std::cos(p.hinge_angle);
            const double sc = p.spine * std::cos(p.spine_angle);
            const bool run = std::abs(rc) >= std::abs(sc); // the longer part along the hinge
            const double part_cos = std::abs(std::cos(run ? p.hinge_angle : p.spine_angle));
            const double other = rc * sc < 0 ? std::abs(run ? sc : rc) : 0.0;
            const bool alone = host.length - other <= 0; // the other part must shrink too
            m << "> 0 and <= " << (alone ? host.length : host.length - other) / part_cos
              << " mm at " << (run ? "HingeAngle " : "SpineAngle ")
              << (run ? p.hinge_angle : p.spine_angle) * deg << "°"
              << (alone ? (run ? ", with Spine shorter too" : ", with Run shorter too") : "")
              << " (the v-fold would span " << hi - lo << " mm along " << host.name << ", which is "
              << host.length << " mm long)";
            range_error(e, name, run ? "Run" : "Spine", run ? p.run : p.spine, "mm", m.str());
        } else if (!(p.offset + lo >= 0 && p.offset + hi <= host.length)) {
            m << ">= " << -lo << " mm and <= " << host.length - hi << " mm (the v-fold spans "
              << hi - lo << " mm of " << host.name << ")";
            range_error(e, name, "Offset", p.offset, "mm", m.str());
        }
    }
    if (e.empty())
        check_part_sizes(scaffold, name, {{"Run", p.run}, {"Spine", p.spine}}, e);
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
    m.tab(host.ground, wing_g, O, A);
    m.tab(host.backdrop, wing_b, O, B);
    m.hinge(wing_g, wing_b, O, P);
    // P travels along the hinge as the host closes: sample its closed form for the sweep.
    double lo = std::min({0.0, along, P.y() - p.offset}),
           hi = std::max({0.0, along, P.y() - p.offset});
    for (int k = 0; k <= 90; ++k) {
        const double y = v_fold_tip(p, host.opening, host.opening * k / 90).y() - p.offset;
        lo = std::min(lo, y);
        hi = std::max(hi, y);
    }
    m.sweeps(p.offset + lo, p.offset + hi);
    // The wings along the spine, a base patch pair in the host's world.
    BasePatchPair local = v_fold_wings(p, host.opening, host.opening);
    BasePatchPair wings = local;
    wings.name = name + ".wings";
    const bool ground_wing_on_x = local.x_axis().dot(A - O) > 0;
    wings.ground = ground_wing_on_x ? wing_g : wing_b;
    wings.backdrop = ground_wing_on_x ? wing_b : wing_g;
    wings.origin = m.world(local.origin);
    wings.axis = m.world(local.axis) - m.world(Vec3::Zero());
    wings.up = m.world(local.up) - m.world(Vec3::Zero());
    m.offer(wings);
    return m.finish();
}

} // namespace popup
