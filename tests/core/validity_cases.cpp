#include "validity_cases.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace popup::fixtures {

Scaffold valid_tent_card()
{
    Scaffold s = make_card(200, 140);
    s.name = "tent fold";
    add_tent_fold(s, 40, 60, 30, 40);
    return s;
}

Scaffold valid_multi_card()
{
    Scaffold s = make_card(240, 140);
    s.name = "tent, step and v-fold";
    add_tent_fold(s, 15, 50, 30, 45);
    add_step_fold(s, 85, 50, 40, 30);
    add_v_fold(s, 160, 50, deg(45), 55, deg(60));
    return s;
}

Scaffold broken_tent_card()
{
    // Built open at 90°: the slopes (25 mm) reach the apex only while sin(θ/2) <= 25/30.
    Scaffold s = make_card_at(200, 140, deg(90));
    s.name = "tent whose slopes are shorter than its feet";
    add_tent_fold(s, 40, 60, 30, 25);
    return s;
}

Scaffold five_bar_card()
{
    Scaffold s = make_card(200, 140);
    s.name = "five-bar loop";
    const double y0 = 50, y1 = 110;
    const Vec3 p1(40, 0, 0), p2(25, 0, 35), p3(-25, 0, 35), p4(-40, 0, 0);
    auto at = [](const Vec3& p, double y) { return Vec3(p.x(), y, p.z()); };
    const int a = add_quad(s, at(p1, y0), at(p1, y1), at(p2, y1), at(p2, y0));
    const int b = add_quad(s, at(p2, y0), at(p2, y1), at(p3, y1), at(p3, y0));
    const int c = add_quad(s, at(p3, y0), at(p3, y1), at(p4, y1), at(p4, y0));
    add_hinge(s, s.ground, a, at(p1, y0), at(p1, y1));
    add_hinge(s, a, b, at(p2, y0), at(p2, y1));
    add_hinge(s, b, c, at(p3, y0), at(p3, y1));
    add_hinge(s, c, s.backdrop, at(p4, y0), at(p4, y1));
    return s;
}

Scaffold chain_card(int links)
{
    Scaffold s = make_card(200, 140);
    s.name = "chain of " + std::to_string(links);
    const double y0 = 50, y1 = 110, r = 40;
    auto at = [&](int k, double y) {
        const double t = M_PI * k / links;
        return k == links ? Vec3(-r, y, 0) : Vec3(r * std::cos(t), y, r * std::sin(t));
    };
    std::vector<int> link;
    for (int k = 0; k < links; ++k)
        link.push_back(add_quad(s, at(k, y0), at(k, y1), at(k + 1, y1), at(k + 1, y0)));
    add_hinge(s, s.ground, link.front(), at(0, y0), at(0, y1));
    for (int k = 1; k < links; ++k)
        add_hinge(s, link[k - 1], link[k], at(k, y0), at(k, y1));
    add_hinge(s, link.back(), s.backdrop, at(links, y0), at(links, y1));
    return s;
}

Scaffold colliding_walls_card()
{
    // Walls of height h standing on each base at distance d from the fold: their tops meet on
    // the mid-plane when tan(θ/2) = h/d, so at 40° for h = d·tan 20°.
    Scaffold s = make_card(200, 140);
    s.name = "walls colliding at 40 degrees";
    const double d = 50, h = d * std::tan(deg(20));
    const int g = add_quad(s, {d, 60, 0}, {d, 120, 0}, {d, 120, h}, {d, 60, 0 + h});
    const int b = add_quad(s, {-d, 80, 0}, {-d, 80, h}, {-d, 140, h}, {-d, 140, 0});
    s.glue.push_back({s.ground, g});
    s.glue.push_back({s.backdrop, b});
    return s;
}

Scaffold sticking_out_tent_card()
{
    Scaffold s = make_card(200, 60);
    s.name = "tent sticking out of the closed card";
    add_tent_fold(s, 40, 60, 30, 40); // closes to a + s = 70 mm on a 60 mm deep card
    return s;
}

} // namespace popup::fixtures
