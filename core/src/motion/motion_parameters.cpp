#include "motion_parameters.hpp"

#include <algorithm>
#include <cmath>

#include "popup/sheets/sheet_layout.hpp"

namespace popup::motion {

constexpr double margin = build_margin;

MotionMechanism rotation_mechanism(double offset, double spine, double run, double arm,
                                   double hinge)
{
    MotionMechanism m;
    m.kind = MotionKind::rotation;
    m.p = {offset, spine, run, arm, hinge};
    return m;
}

MotionMechanism vertical_mechanism(double offset, double side, double height, double wall_angle)
{
    MotionMechanism m;
    m.kind = MotionKind::vertical;
    m.p = {offset, side, height, wall_angle};
    return m;
}

MotionMechanism horizontal_mechanism(double offset, double width, double run_ground,
                                     double run_backdrop, double reach)
{
    MotionMechanism m;
    m.kind = MotionKind::horizontal;
    m.p = {offset, width, run_ground, run_backdrop, reach};
    return m;
}

MotionMechanism diagonal_mechanism(double offset, double run, double hinge_angle, double spine,
                                   double step_offset, double step_width, double run_ground,
                                   double run_backdrop)
{
    MotionMechanism m;
    m.kind = MotionKind::diagonal;
    m.p = {offset, run, hinge_angle, spine, step_offset, step_width, run_ground, run_backdrop};
    return m;
}

MotionMechanism layer_mechanism(double offset, double width, double height, double support,
                                double overhang, double anchor)
{
    MotionMechanism m;
    m.kind = MotionKind::stationary;
    m.p = {offset, width, height, support, overhang, anchor};
    return m;
}

RotationArmParams rotation_params(const MotionMechanism& m)
{
    RotationArmParams r;
    // Off the fold the arm starts at its layer's start, which is at `offset` on the card.
    r.offset = m.p[4] == 0 ? m.p[0] : 0.0;
    r.spine = m.p[1];
    r.run = m.p[2];
    r.arm = m.p[3];
    return r;
}

VBoxFoldParams vertical_params(const MotionMechanism& m)
{
    VBoxFoldParams v;
    v.offset = m.p[0];
    v.side = m.p[1];
    v.height = m.p[2];
    v.wall_angle = m.p[3];
    v.back = false;
    return v;
}

HorizontalTranslationParams horizontal_params(const MotionMechanism& m)
{
    HorizontalTranslationParams h;
    h.offset = m.p[0];
    h.width = m.p[1];
    h.run_ground = m.p[2];
    h.run_backdrop = m.p[3];
    h.reach = m.p[4];
    return h;
}

VFoldParams diagonal_v_fold(const MotionMechanism& m)
{
    VFoldParams v;
    v.offset = m.p[0];
    v.run = m.p[1];
    v.hinge_angle = m.p[2];
    v.spine = m.p[3];
    v.spine_angle = M_PI / 2; // the spine stands at 180°: the thesis's diagonal translation
    return v;
}

StepFoldParams diagonal_step(const MotionMechanism& m)
{
    StepFoldParams s;
    s.offset = m.p[4];
    s.width = m.p[5];
    s.run_ground = m.p[6];
    s.run_backdrop = m.p[7];
    return s;
}

FloatingLayerParams layer_params(const MotionMechanism& m)
{
    FloatingLayerParams f;
    f.offset = m.p[0];
    f.width = m.p[1];
    f.height = m.p[2];
    f.support = m.p[3];
    f.overhang = m.p[4];
    return f;
}

LayerSide rotation_side(const MotionMechanism& m)
{
    return m.p[4] > 0 ? LayerSide::ground : LayerSide::backdrop;
}

const char* to_string(MotionKind kind)
{
    switch (kind) {
    case MotionKind::vertical:
        return "vertical";
    case MotionKind::diagonal:
        return "diagonal";
    case MotionKind::horizontal:
        return "horizontal";
    case MotionKind::rotation:
        return "rotation";
    case MotionKind::stationary:
        return "stationary";
    }
    return "stationary";
}

int parameter_count(MotionKind kind)
{
    switch (kind) {
    case MotionKind::vertical:
        return 4;
    case MotionKind::diagonal:
        return 8;
    case MotionKind::horizontal:
        return 5;
    case MotionKind::rotation:
        return 5;
    case MotionKind::stationary:
        return 6;
    }
    return 0;
}

int active_parameter_count(const MotionMechanism& m)
{
    if (m.kind == MotionKind::rotation && !rotation_off_fold(m))
        return 4;
    return parameter_count(m.kind);
}

bool rotation_off_fold(const MotionMechanism& m)
{
    return m.kind == MotionKind::rotation && m.p[4] != 0;
}

double rotation_layer_height(double run, double arm)
{
    return std::max({run, arm, shortest_crease()}) + margin;
}

FloatingLayerParams rotation_layer(const MotionMechanism& m)
{
    FloatingLayerParams f;
    f.offset = m.p[0];
    f.width = m.p[1];
    f.support = std::abs(m.p[4]);
    f.height = rotation_layer_height(m.p[2], m.p[3]);
    f.overhang = 0;
    return f;
}

ParameterInfo parameter_info(MotionKind kind, int i)
{
    using R = ParameterRole;
    static const ParameterInfo vertical[] = {{"offset", R::position},
                                             {"side", R::length},
                                             {"height", R::length},
                                             {"wall_angle", R::angle}};
    static const ParameterInfo diagonal[] = {
        {"offset", R::position},   {"run", R::length},         {"hinge_angle", R::angle},
        {"spine", R::length},      {"step_offset", R::length}, {"step_width", R::length},
        {"run_ground", R::length}, {"run_backdrop", R::length}};
    static const ParameterInfo horizontal[] = {{"offset", R::position},
                                               {"width", R::length},
                                               {"run_ground", R::length},
                                               {"run_backdrop", R::length},
                                               {"reach", R::length}};
    static const ParameterInfo rotation[] = {{"offset", R::position},
                                             {"spine", R::length},
                                             {"run", R::length},
                                             {"arm", R::length},
                                             {"hinge", R::position}};
    static const ParameterInfo stationary[] = {{"offset", R::position}, {"width", R::length},
                                               {"height", R::length},   {"support", R::length},
                                               {"overhang", R::length}, {"anchor", R::position}};
    switch (kind) {
    case MotionKind::vertical:
        return vertical[i];
    case MotionKind::diagonal:
        return diagonal[i];
    case MotionKind::horizontal:
        return horizontal[i];
    case MotionKind::rotation:
        return rotation[i];
    case MotionKind::stationary:
        return stationary[i];
    }
    return stationary[0];
}

double mechanism_height(const MotionMechanism& m)
{
    switch (m.kind) {
    case MotionKind::vertical:
        return m.p[2];
    case MotionKind::diagonal:
        return m.p[4] + m.p[5] / 2; // the nose on the standing spine
    case MotionKind::stationary:
        return m.p[2];
    case MotionKind::horizontal:
    case MotionKind::rotation:
        return 0.0; // flat on the card when open
    }
    return 0.0;
}

double shortest_crease()
{
    static const double crease = shortest_tabbed_crease(SheetOptions{});
    return crease;
}

} // namespace popup::motion
