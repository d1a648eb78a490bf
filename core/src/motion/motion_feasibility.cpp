#include "motion_feasibility.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "mechanism_parts.hpp"
#include "motion_parameters.hpp"
#include "parameter_table.hpp"
#include "popup/sheets/sheet_layout.hpp"

namespace popup::motion {

namespace {

constexpr double margin = build_margin;

// The first range a mechanism's parameters leave: `name` = `value` must be `must` (no name: the
// whole of `must` says why). Kept unformatted: the search tests feasibility per move and only
// the report needs the words.
struct Violation {
    const char* name = nullptr;
    double value = 0.0;
    const char* must = nullptr;
};

Violation fail(const char* name, double value, const char* range)
{
    return {name, value, range};
}

// A floating layer's legs and platform unfold into one strip, a glue tab at each leg's foot:
// 2 (height + support + overhang) + 2 tabs long. The card's open sheet (2D long, PopUp sizes the
// card to the paper) must hold it, as it must the diagonal's wings (found by drawing random
// feasible off-fold arms: a 76.5 mm layer on 58.8 mm supports unfolded to 286.6 mm, longer than
// A4's printable 277 mm, and the sheets refused the design).
bool layer_strip_fits(const FloatingLayerParams& f, const CardParams& card)
{
    // With an overhang the legs, turned out about their creases, would lie on the platform's
    // overhang: the sheets cut them off at a tab joint, and the platform is the long piece.
    const double strip = f.overhang > 0 ? 2 * (f.support + f.overhang) : 2 * (f.height + f.support);
    return strip + 2 * SheetOptions{}.tab_width <= 2 * card.depth;
}

constexpr double lo_angle = 5 * M_PI / 180, hi_angle = 85 * M_PI / 180;

// A rotation arm on the fold, or on a floating layer's side pair.
Violation rotation_violation(const MotionMechanism& m, const CardParams& card)
{
    const double W = card.width, D = card.depth;
    const RotationArmParams r = rotation_params(m);
    if (!(r.spine >= shortest_crease() && r.spine <= W))
        return fail("spine", r.spine, "in [shortest glued crease, card width]");
    // The wing's width: a glue tab on its crease needs a patch that wide to sit on.
    if (!(r.run >= shortest_crease()))
        return fail("run", r.run, ">= the shortest glued crease");
    if (!(fold_offset(m) >= 0 && fold_offset(m) + r.spine <= W))
        return fail("offset", fold_offset(m), "in [0, card width - spine]");
    if (!rotation_off_fold(m)) {
        if (!(r.run > margin && r.run < D - margin))
            return fail("run", r.run, "in (1, card depth - 1)");
        if (!(r.arm > margin && r.arm <= std::min(r.spine * r.spine / r.run, D) * (1 - 1e-6)))
            return fail("arm", r.arm, "in (1, min(spine²/run, card depth)]");
        return {};
    }
    // On a layer's side pair: the layer's supports and height are glued creases; the wings
    // reach the page beyond the support (D − s) and the support (the layer's height, which
    // rotation_layer_height keeps above Run and Arm).
    const FloatingLayerParams f = rotation_layer(m);
    if (!(f.support >= shortest_crease() && f.support < D - margin))
        return fail("hinge", m.rotation().hinge,
                    "with |hinge| in [shortest glued crease, card depth - 1)");
    if (!(r.run > margin && r.run < D - f.support - margin))
        return fail("run", r.run, "in (1, card depth - |hinge| - 1)");
    if (!(r.arm > margin && r.arm <= r.spine * r.spine / r.run * (1 - 1e-6)))
        return fail("arm", r.arm, "in (1, spine²/run]");
    // One wing is glued to a support along O–S, the diagonal of the support's Spine × Run
    // corner: held to 20°..70° from the support's edges so the glue tab beside it has room
    // (at 5.6°, found on a boxing BVH, the sheets found no room for any tab and the wing was a
    // sliver).
    if (!(r.run >= std::tan(20 * M_PI / 180) * r.spine &&
          r.run <= std::tan(70 * M_PI / 180) * r.spine))
        return fail("run", r.run, "in [tan 20°, tan 70°] × spine (the glued wing's crease)");
    // Closed, the support stands on the page from s to s + height.
    if (!(f.support + f.height < D - margin))
        return fail("hinge", m.rotation().hinge,
                    "with the layer's height under the closed card's top");
    if (!layer_strip_fits(f, card))
        return fail("hinge", m.rotation().hinge,
                    "with the layer's height, unfolded with its tabs, within the card's open "
                    "sheet (2 × depth)");
    return {};
}

// The v-box of a vertical translation.
Violation vertical_violation(const MotionMechanism& m, const CardParams& card)
{
    const double W = card.width, D = card.depth;
    const VBoxFoldParams p = vertical_params(m);
    if (!(p.wall_angle > lo_angle && p.wall_angle < hi_angle))
        return fail("wall_angle", p.wall_angle, "in (5°, 85°)");
    const double across = p.side * std::sin(p.wall_angle);
    const double along = p.side * std::cos(p.wall_angle);
    if (!(p.side > margin && 2 * along >= 2 * margin && across < D - margin))
        return fail("side", p.side, "> 1 mm, its reach inside the page");
    if (!(p.offset >= 0 && p.offset + 2 * along <= W))
        return fail("offset", p.offset, "in [0, card width - 2·side·cos(wall_angle)]");
    if (!(p.height > margin && p.height < D))
        return fail("height", p.height, "in (1, card depth)");
    // Glued creases: the walls' feet and tops (side), the front spine (height) and the top's
    // diagonal (2·side·cos(wall_angle)).
    if (!(std::min({p.side, p.height, 2 * along, across}) >= shortest_crease()))
        return fail("side", p.side,
                    "with height, side·sin(wall_angle) and 2·side·cos(wall_angle) >= the "
                    "shortest glued crease");
    return {};
}

// The step and extruding patch of a horizontal translation.
Violation horizontal_violation(const MotionMechanism& m, const CardParams& card)
{
    const double W = card.width, D = card.depth;
    const HorizontalTranslationParams h = horizontal_params(m);
    if (!(h.width >= std::max(12.0, shortest_crease()) && h.offset >= 0 && h.offset + h.width <= W))
        return fail("width", h.width,
                    ">= 12 mm (two slit bridges), the shortest glued crease, on the card");
    if (!(h.run_ground > margin && h.run_ground < D - margin))
        return fail("run_ground", h.run_ground, "in (1, card depth - 1)");
    if (!(h.run_backdrop > margin && h.run_backdrop < h.run_ground - margin))
        return fail("run_backdrop", h.run_backdrop, "in (1, run_ground - 1)");
    // The step's strips and the extruding patch carry glue tabs: each that wide.
    if (!(std::min({h.run_backdrop, h.reach}) >= shortest_crease()))
        return fail("run_backdrop", h.run_backdrop, "with reach >= the shortest glued crease");
    if (!(h.reach > h.run_ground - h.run_backdrop + margin && h.reach <= D - margin))
        return fail("reach", h.reach, "in (run_ground - run_backdrop + 1, card depth - 1]");
    return {};
}

// The v-fold and its step of a diagonal translation.
Violation diagonal_violation(const MotionMechanism& m, const CardParams& card)
{
    const double W = card.width, D = card.depth;
    const VFoldParams v = diagonal_v_fold(m);
    const StepFoldParams s = diagonal_step(m);
    if (!(v.hinge_angle > lo_angle && v.hinge_angle < hi_angle))
        return fail("hinge_angle", v.hinge_angle, "in (5°, 85°)");
    if (!(v.run > margin && v.run * std::sin(v.hinge_angle) < D - margin))
        return fail("run", v.run, "> 1 mm, its reach inside the page");
    if (!(v.offset >= 0 && v.offset + v.run * std::cos(v.hinge_angle) <= W))
        return fail("offset", v.offset, "in [0, card width - run·cos(hinge_angle)]");
    if (!(v.spine > 4 * margin && v.spine <= std::max(W, D)))
        return fail("spine", v.spine, "in (4, the card's largest extent]");
    if (!(s.offset >= margin && s.width >= margin && s.offset + s.width <= v.spine - margin))
        return fail("step_offset", s.offset, "with step_width inside the spine");
    // The wings are right triangles at 180° (spine standing, O-A flat): at height z the
    // wing reaches run·(1 − z/spine) from the spine; the step's creases must stay on it.
    const double room = v.run * (1 - (s.offset + s.width) / v.spine) - margin;
    // Glued creases: the wings' feet (run), the spine, the step's folds (step_width).
    if (!(std::min({v.run, v.spine, s.width, s.run_ground, s.run_backdrop}) >= shortest_crease()))
        return fail("run", v.run,
                    "with spine, step_width and the step's runs >= the shortest glued crease");
    if (!(s.run_ground > margin && s.run_ground < room))
        return fail("run_ground", s.run_ground, "inside the v-fold's wing");
    if (!(s.run_backdrop > margin && s.run_backdrop < room))
        return fail("run_backdrop", s.run_backdrop, "inside the v-fold's wing");
    return {};
}

// The floating layer of a still part.
Violation layer_violation(const MotionMechanism& m, const CardParams& card)
{
    const double W = card.width, D = card.depth;
    const FloatingLayerParams f = layer_params(m);
    if (!(f.width >= 2 * margin && f.offset >= 0 && f.offset + f.width <= W))
        return fail("width", f.width, ">= 2 mm and on the card");
    if (!(f.support > margin && f.support < D - margin))
        return fail("support", f.support, "in (1, card depth - 1)");
    if (!(f.height > margin && f.height <= 2000))
        return fail("height", f.height, "in (1, 2000]");
    if (!(f.overhang >= 0))
        return fail("overhang", f.overhang, ">= 0");
    // Glued creases: along the fold (width), the end panels' joints (height, support).
    if (!(std::min({f.width, f.height, f.support}) >= shortest_crease()))
        return fail("width", f.width, "with height and support >= the shortest glued crease");
    const double anchor = m.stationary().anchor;
    if (!(std::abs(anchor) <= f.support + f.overhang))
        return fail("anchor", anchor, "on the platform (|anchor| <= support + overhang)");
    if (!layer_strip_fits(f, card))
        return fail("support", f.support,
                    "with height and overhang, unfolded with its tabs, within the card's open "
                    "sheet (2 × depth)");
    return {};
}

Violation first_violation(const MotionMechanism& m, const CardParams& card)
{
    const double W = card.width, D = card.depth;
    for (int i = 0; i < parameter_count(m.kind()); ++i)
        if (!std::isfinite(parameter(m, i)))
            return fail(parameter_info(m.kind(), i).name, parameter(m, i), "finite");
    Violation v;
    switch (m.kind()) {
    case MotionKind::rotation:
        v = rotation_violation(m, card);
        break;
    case MotionKind::vertical:
        v = vertical_violation(m, card);
        break;
    case MotionKind::horizontal:
        v = horizontal_violation(m, card);
        break;
    case MotionKind::diagonal:
        v = diagonal_violation(m, card);
        break;
    case MotionKind::stationary:
        v = layer_violation(m, card);
        break;
    }
    if (v.must)
        return v;
    // Closed (θ = 0) every part must lie inside the card: along the fold within its width, and
    // no higher than the pages (z along the closed pages).
    thread_local std::vector<MechanismPart> closed;
    mechanism_parts(m, 0.0, closed);
    for (const MechanismPart& part : closed)
        for (const Vec3& q : part.vertices)
            if (q.y() < -1e-9 || q.y() > W + 1e-9 || q.z() > D - margin)
                return {nullptr, 0.0, "a part sticks out of the closed card"};
    return {};
}

} // namespace

bool diagonal_wings_fit(const MotionMechanism& m, const CardParams& card)
{
    // The v-fold's two wings are one piece of the sheets, unfolded about their spine O–P: the
    // wing O-A-P (mechanism_parts' first piece) and its mirror across O–P. Across the spine the
    // piece spans twice A's distance from it; along it, the wing's shadow on O–P. The card is
    // the largest whose open sheet (W × 2D) fits the paper, so the piece, grown by a glue tab on
    // each side, must fit W × 2D one way or the other.
    if (m.kind() != MotionKind::diagonal)
        return true;
    thread_local std::vector<MechanismPart> opened;
    mechanism_parts(m, M_PI, opened);
    const Vec3 &O = opened[0].vertices[0], &A = opened[0].vertices[1], &P = opened[0].vertices[2];
    const Vec3 spine = P - O;
    const double length = spine.norm();
    if (!(length > 0))
        return false;
    const double across = 2 * (A - O).cross(spine).norm() / length;
    const double along_a = (A - O).dot(spine) / length;
    const double along = std::max(length, along_a) - std::min(0.0, along_a);
    const double tabs = 2 * SheetOptions{}.tab_width;
    const double W = card.width, D2 = 2 * card.depth;
    return (across + tabs <= D2 && along + tabs <= W) || (across + tabs <= W && along + tabs <= D2);
}

std::string infeasibility(const MotionMechanism& m, const CardParams& card)
{
    const Violation v = first_violation(m, card);
    if (!v.must)
        return {};
    if (!v.name)
        return v.must;
    std::ostringstream s;
    s << v.name << " = " << v.value << " must be " << v.must;
    return s.str();
}

bool feasible(const MotionMechanism& m, const CardParams& card)
{
    return !first_violation(m, card).must;
}

} // namespace popup::motion
