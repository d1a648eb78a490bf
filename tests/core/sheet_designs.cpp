#include "sheet_designs.hpp"

#include <cmath>
#include <stdexcept>

#include "popup/mechanisms/box_fold.hpp"
#include "popup/mechanisms/floating_layer.hpp"
#include "popup/mechanisms/horizontal_translation.hpp"
#include "popup/mechanisms/rotation_arm.hpp"
#include "popup/mechanisms/step_fold.hpp"
#include "popup/mechanisms/tent_fold.hpp"
#include "popup/mechanisms/v_box_fold.hpp"
#include "popup/mechanisms/v_fold.hpp"
#include "popup/model/card.hpp"

namespace popup::fixtures {

MechanismParts must(Result<MechanismParts> r, const std::string& what)
{
    if (!r.ok)
        throw std::runtime_error(what + ": " + r.diagnostics.front().message);
    return r.value;
}

StepFoldParams step(double offset, double width, double run_ground, double run_backdrop)
{
    StepFoldParams p;
    p.offset = offset;
    p.width = width;
    p.run_ground = run_ground;
    p.run_backdrop = run_backdrop;
    return p;
}

BoxFoldParams box(double offset, double width, double depth, double height)
{
    BoxFoldParams p;
    p.offset = offset;
    p.width = width;
    p.depth_ground = depth;
    p.depth_backdrop = depth;
    p.height = height;
    return p;
}

namespace {

constexpr double degree = M_PI / 180.0;

Scaffold card(double width, double depth)
{
    CardParams p;
    p.width = width;
    p.depth = depth;
    return make_card(p).value;
}

TentFoldParams tent(double offset, double width, double foot, double slope)
{
    TentFoldParams p;
    p.offset = offset;
    p.width = width;
    p.foot = foot;
    p.foot_backdrop = foot;
    p.slope = slope;
    return p;
}

FloatingLayerParams layer(double offset, double width, double height, double support,
                          double overhang)
{
    FloatingLayerParams p;
    p.offset = offset;
    p.width = width;
    p.height = height;
    p.support = support;
    p.overhang = overhang;
    return p;
}

} // namespace

std::vector<NamedDesign> single_mechanism_cards()
{
    std::vector<NamedDesign> designs;
    auto add = [&](const std::string& name, auto build) {
        Scaffold s = card(200, 140);
        build(s, central_fold(s));
        designs.push_back({name, s});
    };
    add("tent", [](Scaffold& s, const BasePatchPair& h) {
        must(add_tent_fold(s, h, tent(60, 60, 30, 40)), "tent");
    });
    add("step", [](Scaffold& s, const BasePatchPair& h) {
        must(add_step_fold(s, h, step(60, 60, 30, 20)), "step");
    });
    add("v-fold", [](Scaffold& s, const BasePatchPair& h) {
        VFoldParams p;
        p.offset = 60;
        must(add_v_fold(s, h, p), "v-fold");
    });
    add("box", [](Scaffold& s, const BasePatchPair& h) {
        must(add_box_fold(s, h, box(60, 80, 30, 30)), "box");
    });
    add("floating layer", [](Scaffold& s, const BasePatchPair& h) {
        must(add_floating_layer(s, h, layer(60, 60, 25, 20, 15)), "floating layer");
    });
    add("v-box", [](Scaffold& s, const BasePatchPair& h) {
        VBoxFoldParams p;
        p.offset = 60;
        must(add_v_box_fold(s, h, p), "v-box");
    });
    add("vertical translation", [](Scaffold& s, const BasePatchPair& h) {
        VBoxFoldParams p;
        p.offset = 60;
        must(add_vertical_translation(s, h, p), "vertical translation");
    });
    add("horizontal translation", [](Scaffold& s, const BasePatchPair& h) {
        HorizontalTranslationParams p;
        p.offset = 60;
        must(add_horizontal_translation(s, h, p), "horizontal translation");
    });
    add("rotation arm", [](Scaffold& s, const BasePatchPair& h) {
        RotationArmParams p;
        p.offset = 60;
        must(add_rotation_arm(s, h, p), "rotation arm");
    });
    add("diagonal translation", [](Scaffold& s, const BasePatchPair& h) {
        VFoldParams p;
        p.offset = 40;
        p.run = 70;
        p.spine = 75;
        const MechanismParts v = must(add_v_fold(s, h, p), "v-fold");
        must(add_step_fold(s, v.offered.front(), step(10, 20, 15, 10)), "diagonal step");
    });
    return designs;
}

Scaffold demo_card()
{
    Scaffold s = card(210, 148.5);
    const MechanismParts b = must(add_box_fold(s, central_fold(s), box(60, 100, 30, 30)), "box");
    must(add_tent_fold(s, b.offered[0], tent(4, 26, 10, 14)), "tent");
    must(add_floating_layer(s, b.offered[0], layer(40, 30, 10, 8, 5)), "floating layer");
    RotationArmParams arm;
    arm.offset = 85;
    arm.spine = 15;
    arm.run = 10;
    arm.arm = 12;
    must(add_rotation_arm(s, b.offered[0], arm), "rotation arm");
    must(add_step_fold(s, b.offered[1], step(10, 60, 15, 15)), "step");
    VFoldParams v;
    v.offset = 25;
    v.run = 40;
    v.hinge_angle = 45 * degree;
    v.spine = 45;
    v.spine_angle = 60 * degree;
    must(add_v_fold(s, central_fold(s), v), "v-fold");
    VBoxFoldParams vb;
    vb.offset = 185;
    vb.side = 10;
    vb.height = 8;
    vb.wall_angle = 45 * degree;
    must(add_v_box_fold(s, central_fold(s), vb), "v-box");
    return s;
}

Scaffold many_piece_card(int boxes)
{
    Scaffold s = card(240, 120);
    const double pitch = 240.0 / boxes;
    for (int k = 0; k < boxes; ++k) {
        const std::string n = "Box" + std::to_string(k);
        const MechanismParts b =
            must(add_box_fold(s, central_fold(s), box(k * pitch + 5, pitch - 10, 30, 30), n), n);
        must(add_tent_fold(s, b.offered[0], tent(2, 0.3 * (pitch - 10), 10, 14), n + "Tent"),
             n + "Tent");
        must(add_floating_layer(s, b.offered[0],
                                layer(0.45 * (pitch - 10), 0.5 * (pitch - 10), 10, 8, 5),
                                n + "Layer"),
             n + "Layer");
        must(add_step_fold(s, b.offered[1], step(5, pitch - 20, 12, 12), n + "StepG"), n);
        must(add_step_fold(s, b.offered[2], step(5, pitch - 20, 12, 12), n + "StepB"), n);
    }
    return s;
}

} // namespace popup::fixtures
