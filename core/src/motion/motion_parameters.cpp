#include "motion_parameters.hpp"

#include <algorithm>
#include <cmath>

#include "popup/sheets/sheet_layout.hpp"

namespace popup::motion {

constexpr double margin = build_margin;

MotionMechanism default_mechanism(MotionKind kind)
{
    switch (kind) {
    case MotionKind::vertical:
        return {VerticalMotion{}};
    case MotionKind::diagonal:
        return {DiagonalMotion{}};
    case MotionKind::horizontal:
        return {HorizontalMotion{}};
    case MotionKind::rotation:
        return {RotationMotion{}};
    case MotionKind::stationary:
        break;
    }
    return {StationaryMotion{}};
}

MotionMechanism rotation_mechanism(double offset, double spine, double run, double arm,
                                   double hinge)
{
    RotationMotion r;
    r.offset = offset;
    r.spine = spine;
    r.run = run;
    r.arm = arm;
    r.hinge = hinge;
    return {r};
}

MotionMechanism vertical_mechanism(double offset, double side, double height, double wall_angle)
{
    VerticalMotion v;
    v.offset = offset;
    v.side = side;
    v.height = height;
    v.wall_angle = wall_angle;
    return {v};
}

MotionMechanism horizontal_mechanism(double offset, double width, double run_ground,
                                     double run_backdrop, double reach)
{
    HorizontalMotion h;
    h.offset = offset;
    h.width = width;
    h.run_ground = run_ground;
    h.run_backdrop = run_backdrop;
    h.reach = reach;
    return {h};
}

MotionMechanism diagonal_mechanism(double offset, double run, double hinge_angle, double spine,
                                   double step_offset, double step_width, double run_ground,
                                   double run_backdrop)
{
    DiagonalMotion d;
    d.v_fold.offset = offset;
    d.v_fold.run = run;
    d.v_fold.hinge_angle = hinge_angle;
    d.v_fold.spine = spine;
    d.step.offset = step_offset;
    d.step.width = step_width;
    d.step.run_ground = run_ground;
    d.step.run_backdrop = run_backdrop;
    return {d};
}

MotionMechanism layer_mechanism(double offset, double width, double height, double support,
                                double overhang, double anchor)
{
    StationaryMotion s;
    s.offset = offset;
    s.width = width;
    s.height = height;
    s.support = support;
    s.overhang = overhang;
    s.anchor = anchor;
    return {s};
}

RotationArmParams rotation_params(const MotionMechanism& m)
{
    RotationArmParams r = m.rotation();
    // Off the fold the arm starts at its layer's start, which is at `offset` on the card.
    if (rotation_off_fold(m))
        r.offset = 0.0;
    return r;
}

VBoxFoldParams vertical_params(const MotionMechanism& m)
{
    return m.vertical();
}

HorizontalTranslationParams horizontal_params(const MotionMechanism& m)
{
    return m.horizontal();
}

VFoldParams diagonal_v_fold(const MotionMechanism& m)
{
    return m.diagonal().v_fold;
}

StepFoldParams diagonal_step(const MotionMechanism& m)
{
    return m.diagonal().step;
}

FloatingLayerParams layer_params(const MotionMechanism& m)
{
    return m.stationary();
}

LayerSide rotation_side(const MotionMechanism& m)
{
    return m.rotation().hinge > 0 ? LayerSide::ground : LayerSide::backdrop;
}

double& fold_offset(MotionMechanism& m)
{
    switch (m.kind()) {
    case MotionKind::vertical:
        return m.vertical().offset;
    case MotionKind::diagonal:
        return m.diagonal().v_fold.offset;
    case MotionKind::horizontal:
        return m.horizontal().offset;
    case MotionKind::rotation:
        return m.rotation().offset;
    case MotionKind::stationary:
        break;
    }
    return m.stationary().offset;
}

double fold_offset(const MotionMechanism& m)
{
    return fold_offset(const_cast<MotionMechanism&>(m)); // reads only
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

bool rotation_off_fold(const MotionMechanism& m)
{
    return m.kind() == MotionKind::rotation && m.rotation().hinge != 0;
}

double rotation_layer_height(double run, double arm)
{
    return std::max({run, arm, shortest_crease()}) + margin;
}

FloatingLayerParams rotation_layer(const MotionMechanism& m)
{
    const RotationMotion& r = m.rotation();
    FloatingLayerParams f;
    f.offset = r.offset;
    f.width = r.spine;
    f.support = std::abs(r.hinge);
    f.height = rotation_layer_height(r.run, r.arm);
    f.overhang = 0;
    return f;
}

double mechanism_height(const MotionMechanism& m)
{
    switch (m.kind()) {
    case MotionKind::vertical:
        return m.vertical().height;
    case MotionKind::diagonal: {
        const StepFoldParams& s = m.diagonal().step;
        return s.offset + s.width / 2; // the nose on the standing spine
    }
    case MotionKind::stationary:
        return m.stationary().height;
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
