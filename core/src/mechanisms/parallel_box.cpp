#include "parallel_box.hpp"

#include <cmath>

namespace popup {

void build_parallel_box(MechanismBuilder& m, double y0, double y1, const ParallelSection& s)
{
    const double g = s.ground, b = s.backdrop, c = s.height;
    const double og = g + s.overhang, ob = b + s.overhang; // how far the top reaches
    const BasePatchPair& host = m.host();
    const std::string& name = m.name();
    // Local section at the design state: C on x = 0 from the hinge up to the top, L at x = g,
    // R at x = −b, the top at z = c. Outlines wind so normals face out of the box.
    const int C =
        m.patch({{0, y0, 0}, {0, y1, 0}, {0, y1, c}, {0, y0, c}}, PatchRole::support, "C");
    const int L =
        m.patch({{g, y0, 0}, {g, y1, 0}, {g, y1, c}, {g, y0, c}}, PatchRole::support, "L");
    const int R =
        m.patch({{-b, y0, 0}, {-b, y0, c}, {-b, y1, c}, {-b, y1, 0}}, PatchRole::support, "R");
    const int TG =
        m.patch({{0, y0, c}, {og, y0, c}, {og, y1, c}, {0, y1, c}}, PatchRole::top, "TG");
    const int TB =
        m.patch({{-ob, y0, c}, {0, y0, c}, {0, y1, c}, {-ob, y1, c}}, PatchRole::top, "TB");
    m.tab(host.ground, L, {g, y0, 0}, {g, y1, 0});
    m.tab(host.backdrop, R, {-b, y0, 0}, {-b, y1, 0});
    m.tab(host.ground, C, {0, y0, 0}, {0, y1, 0});
    m.tab(host.backdrop, C, {0, y0, 0}, {0, y1, 0});
    m.tab(C, TG, {0, y0, c}, {0, y1, c});
    m.tab(C, TB, {0, y0, c}, {0, y1, c});
    // The top crease itself: redundant for the motion (C holds both halves on that line), but it
    // is what makes L, TG, TB and R one strip of paper.
    m.hinge(TG, TB, {0, y0, c}, {0, y1, c}, FoldDirection::valley);
    if (s.overhang > 0) {
        // The top reaches past the legs: their creases cross its paper, so the legs are sheets
        // of their own, glued under it.
        m.tab(L, TG, {g, y0, c}, {g, y1, c});
        m.tab(R, TB, {-b, y0, c}, {-b, y1, c});
    } else {
        m.hinge(L, TG, {g, y0, c}, {g, y1, c});
        m.hinge(R, TB, {-b, y0, c}, {-b, y1, c});
    }
    // End panels: flat at the design state, their crease must pop outward (a mountain seen from
    // the outside) or it would run into the other end.
    // Several pairs per end are strips stacked up the end: their creases share one line and
    // never cross (thesis §4.1).
    auto panels = [&](double y, bool outward_is_plus, const std::string& left,
                      const std::string& right) {
        const int n = s.panel_pairs;
        for (int k = 0; k < n; ++k) {
            const double z0 = c * k / n, z1 = c * (k + 1) / n;
            std::vector<Vec3> l{{0, y, z0}, {g, y, z0}, {g, y, z1}, {0, y, z1}};
            std::vector<Vec3> rr{{-b, y, z0}, {0, y, z0}, {0, y, z1}, {-b, y, z1}};
            if (outward_is_plus) {
                l = {{0, y, z0}, {0, y, z1}, {g, y, z1}, {g, y, z0}};
                rr = {{-b, y, z0}, {-b, y, z1}, {0, y, z1}, {0, y, z0}};
            }
            const std::string suffix = n == 1 ? "" : std::to_string(k + 1);
            const PatchRole role = outward_is_plus ? PatchRole::back : PatchRole::front;
            const int pl = m.patch(l, role, left + suffix);
            const int pr = m.patch(rr, role, right + suffix);
            m.tab(L, pl, {g, y, z0}, {g, y, z1});
            m.tab(R, pr, {-b, y, z0}, {-b, y, z1});
            m.hinge(pl, pr, {0, y, z0}, {0, y, z1}, FoldDirection::mountain);
        }
    };
    if (s.front)
        panels(y0, false, "FL", "FR");
    if (s.back)
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
    top.length = y1 - y0;
    top.ground_depth = og;
    top.backdrop_depth = ob;
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
    side_l.length = y1 - y0;
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
    side_r.length = y1 - y0;
    side_r.ground_depth = c;
    side_r.backdrop_depth = host.backdrop_depth - b;
    m.offer(side_r);
    // Closed, each end crease stands out of its end by the box's half depth (thesis §4.2.2).
    const double reach = (s.front || s.back) ? g : 0.0;
    m.sweeps(y0 - (s.front ? reach : 0.0), y1 + (s.back ? reach : 0.0));
}

} // namespace popup
