#include "popup/mechanisms/box_fold.hpp"

#include <cmath>
#include <sstream>

#include "mechanism_builder.hpp"

namespace popup {

BoxSection box_fold_section(const BoxFoldParams& p, double opening)
{
    // Sides stay parallel to C, which stays on the bisector; the end crease's foot sits where the
    // two end panels (rectangles g × c) meet (docs/MATH.md, Box fold).
    const double d = opening / 2, g = p.depth_ground;
    BoxSection s;
    s.top = {0, p.height};
    s.side_ground_top = Vec2(g * std::sin(d), g * std::cos(d) + p.height);
    s.side_backdrop_top = Vec2(-g * std::sin(d), g * std::cos(d) + p.height);
    s.crease_foot = {0, g * std::cos(d)};
    s.crease_out = g * std::cos(d);
    return s;
}

Result<MechanismParts> add_box_fold(Scaffold& scaffold, const BasePatchPair& host,
                                    const BoxFoldParams& p, const std::string& name)
{
    Result<MechanismParts> r;
    Diagnostics& e = r.diagnostics;
    check_placement(name, host, p, e);
    if (std::abs(host.opening - M_PI) > 1e-9) {
        std::ostringstream m;
        m << name << ": host " << host.name << " is open " << host.opening * 180 / M_PI
          << "° at the design state; a box fold needs a host open flat (180°)";
        e.push_back({"bad_host", m.str(), name + ".Host"});
    }
    std::ostringstream gmax, bmax;
    gmax << "> 0 and <= " << host.ground_depth << " mm (the depth of the host's ground)";
    bmax << "> 0 and <= " << host.backdrop_depth << " mm (the depth of the host's backdrop)";
    if (!(p.depth_ground > 0 && p.depth_ground <= host.ground_depth))
        range_error(e, name, "DepthGround", p.depth_ground, "mm", gmax.str());
    if (!(p.depth_backdrop > 0 && p.depth_backdrop <= host.backdrop_depth))
        range_error(e, name, "DepthBackdrop", p.depth_backdrop, "mm", bmax.str());
    if (!(p.height > 0 && p.height <= 2000))
        range_error(e, name, "Height", p.height, "mm", "> 0 and <= 2000 mm");
    if (e.empty() && (p.front || p.back) && p.depth_backdrop != p.depth_ground) {
        std::ostringstream m;
        m << "equal to DepthGround (" << p.depth_ground
          << " mm) while the box has front or back panels: otherwise C turns away from the page "
             "and the box cannot close (docs/MATH.md, Box fold)";
        range_error(e, name, "DepthBackdrop", p.depth_backdrop, "mm", m.str());
    }
    if (!e.empty()) {
        r.ok = false;
        return r;
    }
    const double g = p.depth_ground, b = p.depth_backdrop, c = p.height;
    const double y0 = p.offset, y1 = p.offset + p.width;
    MechanismBuilder m(scaffold, host, name);
    // Local section at the design state: C on x = 0 from the hinge up to the top, L at x = g,
    // R at x = −b, the top at z = c. Outlines wind so normals face out of the box.
    const int C =
        m.patch({{0, y0, 0}, {0, y1, 0}, {0, y1, c}, {0, y0, c}}, PatchRole::support, "C");
    const int L =
        m.patch({{g, y0, 0}, {g, y1, 0}, {g, y1, c}, {g, y0, c}}, PatchRole::support, "L");
    const int R =
        m.patch({{-b, y0, 0}, {-b, y0, c}, {-b, y1, c}, {-b, y1, 0}}, PatchRole::support, "R");
    const int TG = m.patch({{0, y0, c}, {g, y0, c}, {g, y1, c}, {0, y1, c}}, PatchRole::top, "TG");
    const int TB =
        m.patch({{-b, y0, c}, {0, y0, c}, {0, y1, c}, {-b, y1, c}}, PatchRole::top, "TB");
    m.hinge(host.ground, L, {g, y0, 0}, {g, y1, 0});
    m.hinge(host.backdrop, R, {-b, y0, 0}, {-b, y1, 0});
    m.hinge(host.ground, C, {0, y0, 0}, {0, y1, 0});
    m.hinge(host.backdrop, C, {0, y0, 0}, {0, y1, 0});
    m.hinge(C, TG, {0, y0, c}, {0, y1, c});
    m.hinge(C, TB, {0, y0, c}, {0, y1, c});
    m.hinge(L, TG, {g, y0, c}, {g, y1, c});
    m.hinge(R, TB, {-b, y0, c}, {-b, y1, c});
    // End panels: flat at the design state, their crease must pop outward (a mountain seen from
    // the outside) or it would run into the other end.
    auto panels = [&](double y, bool outward_is_plus, const char* left, const char* right) {
        std::vector<Vec3> l{{0, y, 0}, {g, y, 0}, {g, y, c}, {0, y, c}};
        std::vector<Vec3> rr{{-b, y, 0}, {0, y, 0}, {0, y, c}, {-b, y, c}};
        if (outward_is_plus) {
            l = {{0, y, 0}, {0, y, c}, {g, y, c}, {g, y, 0}};
            rr = {{-b, y, 0}, {-b, y, c}, {0, y, c}, {0, y, 0}};
        }
        const PatchRole role = outward_is_plus ? PatchRole::back : PatchRole::front;
        const int pl = m.patch(l, role, left);
        const int pr = m.patch(rr, role, right);
        m.hinge(L, pl, {g, y, 0}, {g, y, c});
        m.hinge(R, pr, {-b, y, 0}, {-b, y, c});
        m.hinge(pl, pr, {0, y, 0}, {0, y, c}, FoldDirection::mountain);
    };
    if (p.front)
        panels(y0, false, "FL", "FR");
    if (p.back)
        panels(y1, true, "BL", "BR");

    const Vec3 up = host.up, x = host.x_axis();
    BasePatchPair top;
    top.name = name + ".top";
    top.ground = TG;
    top.backdrop = TB;
    top.origin = m.world({0, y0, c});
    top.axis = host.axis;
    top.up = up;
    top.opening = M_PI;
    top.length = p.width;
    top.ground_depth = g;
    top.backdrop_depth = b;
    m.offer(top);
    // The sides with the host's patch outside the box: right angles at the design state.
    BasePatchPair side_l;
    side_l.name = name + ".side_ground";
    side_l.ground = host.ground;
    side_l.backdrop = L;
    side_l.origin = m.world({g, y0, 0});
    side_l.axis = host.axis;
    side_l.up = (x + up).normalized();
    side_l.opening = M_PI / 2;
    side_l.length = p.width;
    side_l.ground_depth = host.ground_depth - g;
    side_l.backdrop_depth = c;
    m.offer(side_l);
    BasePatchPair side_r;
    side_r.name = name + ".side_backdrop";
    side_r.ground = R;
    side_r.backdrop = host.backdrop;
    side_r.origin = m.world({-b, y0, 0});
    side_r.axis = host.axis;
    side_r.up = (up - x).normalized();
    side_r.opening = M_PI / 2;
    side_r.length = p.width;
    side_r.ground_depth = c;
    side_r.backdrop_depth = host.backdrop_depth - b;
    m.offer(side_r);
    // Closed, each end crease stands out of its end by the box's half depth (thesis §4.2.2).
    const double reach = (p.front || p.back) ? g : 0.0;
    m.sweeps(y0 - (p.front ? reach : 0.0), y1 + (p.back ? reach : 0.0));
    r.value = m.finish();
    return r;
}

} // namespace popup
