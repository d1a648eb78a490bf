#include "test_support.hpp"

#include <algorithm>
#include <cmath>

#include "popup/model/card.hpp"

namespace popup::fixtures {

namespace {
// Point at distance r from the central fold on the ground (r > 0) or the backdrop (r < 0), at
// position y along the fold, when the card is open at `theta`.
Vec3 on_base(double r, double y, double theta)
{
    const double s = std::sin(theta / 2), c = std::cos(theta / 2);
    return r >= 0 ? Vec3(r * s, y, r * c) : Vec3(r * s, y, -r * c);
}
} // namespace

Scaffold make_card(double width, double depth)
{
    Scaffold s;
    s.name = "card";
    Patch ground;
    ground.id = 0;
    ground.name = "ground";
    ground.role = PatchRole::ground;
    ground.outer = {{0, 0, 0}, {depth, 0, 0}, {depth, width, 0}, {0, width, 0}};
    Patch backdrop;
    backdrop.id = 1;
    backdrop.name = "backdrop";
    backdrop.role = PatchRole::backdrop;
    backdrop.outer = {{-depth, 0, 0}, {0, 0, 0}, {0, width, 0}, {-depth, width, 0}};
    s.patches = {ground, backdrop};
    s.ground = 0;
    s.backdrop = 1;
    s.hinges.push_back({0, 0, 1, {0, 0, 0}, {0, width, 0}, FoldDirection::valley});
    for (Patch& p : s.patches)
        p.derive_frame();
    return s;
}

Scaffold make_card_at(double width, double depth, double theta)
{
    Scaffold s = make_card(width, depth);
    s.design_angle = theta;
    s.patches[0].outer = {on_base(0, 0, theta), on_base(depth, 0, theta),
                          on_base(depth, width, theta), on_base(0, width, theta)};
    s.patches[1].outer = {on_base(-depth, 0, theta), on_base(0, 0, theta), on_base(0, width, theta),
                          on_base(-depth, width, theta)};
    for (Patch& p : s.patches)
        p.derive_frame();
    return s;
}

Scaffold generator_card(double width, double depth)
{
    CardParams p;
    p.width = width;
    p.depth = depth;
    return popup::make_card(p).value;
}

int next_patch_id(const Scaffold& s)
{
    int id = 0;
    for (const Patch& p : s.patches)
        id = std::max(id, p.id + 1);
    return id;
}

int add_quad(Scaffold& s, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
             PatchRole role)
{
    Patch p;
    p.id = next_patch_id(s);
    p.name = std::string(to_string(role)) + std::to_string(p.id);
    p.role = role;
    p.outer = {a, b, c, d};
    p.derive_frame();
    s.patches.push_back(p);
    return p.id;
}

void add_hinge(Scaffold& s, int a, int b, const Vec3& from, const Vec3& to, FoldDirection direction)
{
    int id = 0;
    for (const Hinge& h : s.hinges)
        id = std::max(id, h.id + 1);
    s.hinges.push_back({id, a, b, from, to, direction});
}

std::vector<int> add_tent_fold(Scaffold& s, double y0, double width, double foot, double slope)
{
    const double theta = s.design_angle;
    const double y1 = y0 + width;
    const double half_gap = foot * std::sin(theta / 2);
    const double apex_z =
        foot * std::cos(theta / 2) + std::sqrt(slope * slope - half_gap * half_gap);
    const Vec3 a0 = on_base(foot, y0, theta), a1 = on_base(foot, y1, theta);
    const Vec3 d0 = on_base(-foot, y0, theta), d1 = on_base(-foot, y1, theta);
    const Vec3 c0(0, y0, apex_z), c1(0, y1, apex_z);
    const int g = add_quad(s, a0, a1, c1, c0, PatchRole::support);
    const int b = add_quad(s, c0, c1, d1, d0, PatchRole::support);
    add_hinge(s, s.ground, g, a0, a1);
    add_hinge(s, s.backdrop, b, d0, d1);
    add_hinge(s, g, b, c0, c1);
    return {g, b};
}

std::vector<int> add_step_fold(Scaffold& s, double y0, double width, double a, double b)
{
    const double y1 = y0 + width;
    const Vec3 A0(a, y0, 0), A1(a, y1, 0), C0(a - b, y0, 0), C1(a - b, y1, 0);
    const Vec3 D0(-b, y0, 0), D1(-b, y1, 0);
    const int riser = add_quad(s, C0, A0, A1, C1, PatchRole::front);
    const int tread = add_quad(s, D0, C0, C1, D1, PatchRole::top);
    // The riser lies folded back onto the ground and the tread onto the backdrop; both lift
    // toward the base's printed side, and the step's nose is a mountain.
    add_hinge(s, s.ground, riser, A0, A1, FoldDirection::valley);
    add_hinge(s, s.backdrop, tread, D0, D1, FoldDirection::valley);
    add_hinge(s, riser, tread, C0, C1, FoldDirection::mountain);
    return {riser, tread};
}

std::vector<int> add_v_fold(Scaffold& s, double y0, double r, double alpha, double length,
                            double gamma)
{
    const Vec3 O(0, y0, 0);
    const Vec3 A(r * std::sin(alpha), y0 + r * std::cos(alpha), 0);
    const Vec3 B(-r * std::sin(alpha), y0 + r * std::cos(alpha), 0);
    const Vec3 P(0, y0 + length * std::cos(gamma), length * std::sin(gamma));
    auto triangle = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
        Patch p;
        p.id = next_patch_id(s);
        p.name = "v" + std::to_string(p.id);
        p.role = PatchRole::support;
        p.outer = {a, b, c};
        p.derive_frame();
        s.patches.push_back(p);
        return p.id;
    };
    const int g = triangle(O, A, P);
    const int b = triangle(O, P, B);
    add_hinge(s, s.ground, g, O, A);
    add_hinge(s, s.backdrop, b, O, B);
    add_hinge(s, g, b, O, P);
    return {g, b};
}

std::vector<double> angle_range(double from_deg, double to_deg, int count)
{
    std::vector<double> out;
    for (int k = 0; k < count; ++k)
        out.push_back(deg(from_deg + (to_deg - from_deg) * k / (count - 1)));
    return out;
}

double max_residual(const FoldSweep& sweep)
{
    double r = 0.0;
    for (const FoldState& st : sweep.states)
        r = std::max(r, st.hinge_residual);
    return r;
}

double max_strain(const FoldSweep& sweep)
{
    double r = 0.0;
    for (const FoldState& st : sweep.states)
        r = std::max(r, st.edge_strain);
    return r;
}

Vec3 world_point(const Scaffold& s, const FoldState& state, int id, const Vec3& x)
{
    return state.poses[s.patch_index(id)].apply(x);
}

} // namespace popup::fixtures
