#include "motion_mechanism.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "popup/mechanisms/floating_layer.hpp"
#include "popup/mechanisms/horizontal_translation.hpp"
#include "popup/mechanisms/rotation_arm.hpp"
#include "popup/mechanisms/step_fold.hpp"
#include "popup/mechanisms/v_box_fold.hpp"
#include "popup/mechanisms/v_fold.hpp"
#include "popup/sheets/sheet_layout.hpp"

namespace popup::motion {

namespace {

constexpr double margin = 1.0; // mm kept inside every generator range, so the build succeeds

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

Vec2 ground_dir(double theta)
{
    return {std::sin(theta / 2), std::cos(theta / 2)};
}
Vec2 backdrop_dir(double theta)
{
    return {-std::sin(theta / 2), std::cos(theta / 2)};
}
Vec3 at(const Vec2& section, double y)
{
    return {section.x(), y, section.y()};
}

// Both points at distances r1, r2, r3 from p1, p2, p3 (empty when the spheres miss).
std::vector<Vec3> trilaterate(const Vec3& p1, const Vec3& p2, const Vec3& p3, double r1, double r2,
                              double r3)
{
    const double d = (p2 - p1).norm();
    if (d <= 1e-12)
        return {};
    const Vec3 ex = (p2 - p1) / d;
    const double i = ex.dot(p3 - p1);
    Vec3 ey = p3 - p1 - i * ex;
    const double j = ey.norm();
    if (j <= 1e-12)
        return {};
    ey /= j;
    const Vec3 ez = ex.cross(ey);
    const double x = (r1 * r1 - r2 * r2 + d * d) / (2 * d);
    const double y = (r1 * r1 - r3 * r3 + i * i + j * j) / (2 * j) - i * x / j;
    const double z = std::sqrt(std::max(0.0, r1 * r1 - x * x - y * y));
    const Vec3 base = p1 + x * ex + y * ey;
    return {base + z * ez, base - z * ez};
}

LayerSide rotation_side(const MotionMechanism& m)
{
    return m.p[4] > 0 ? LayerSide::ground : LayerSide::backdrop;
}

/// Writes pieces over `out`'s, keeping their storage (the volumes call mechanism_parts in a loop).
struct PartWriter {
    std::vector<MechanismPart>& out;
    std::size_t count = 0;
    std::vector<Vec3>& add(int side, std::initializer_list<Vec3> vertices)
    {
        if (count == out.size())
            out.emplace_back();
        MechanismPart& part = out[count++];
        part.side = side;
        part.vertices.assign(vertices);
        return part.vertices;
    }
};

/// The parallel section (docs/MATH.md, Box fold / Floating layer): C on the bisector from the
/// hinge up to c·ẑ, the legs L, R at s·g, s·b, the top halves reaching s + o, and the end panels
/// from the legs' ends to the end creases g·cos(θ/2) out of each end.
void layer_parts(const FloatingLayerParams& f, double theta, PartWriter& parts)
{
    const double d = theta / 2;
    const Vec2 g = ground_dir(theta), b = backdrop_dir(theta);
    const double c = f.height, s = f.support, reach = f.support + f.overhang;
    const Vec2 top(0, c);
    const double y0 = f.offset, y1 = f.offset + f.width;
    auto strip = [&](const Vec2& p, const Vec2& q, int side) {
        parts.add(side, {at(p, y0), at(q, y0), at(q, y1), at(p, y1)});
    };
    strip(Vec2(0, 0), top, 0);
    strip(s * g, top + s * g, +1);
    strip(s * b, top + s * b, -1);
    strip(top, top + reach * g, +1);
    strip(top, top + reach * b, -1);
    const double out = s * std::cos(d);
    for (double y : {y0, y1}) {
        const double crease = y == y0 ? y0 - out : y1 + out;
        const Vec3 foot(0, crease, out), head(0, crease, out + c);
        parts.add(+1, {at(s * g, y), at(top + s * g, y), head, foot});
        parts.add(-1, {at(s * b, y), at(top + s * b, y), head, foot});
    }
}

/// The report's row of a floating layer (the stationary mapping's, or an off-fold arm's host).
FittedMechanism layer_row(const FloatingLayerParams& f, const std::string& name,
                          const std::string& host)
{
    FittedMechanism row;
    row.type = "floating_layer";
    row.name = name;
    row.host = host;
    row.parameters = {{"offset", f.offset},
                      {"width", f.width},
                      {"height", f.height},
                      {"support", f.support},
                      {"overhang", f.overhang}};
    return row;
}

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

} // namespace

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

Vec3 mechanism_point(const MotionMechanism& m, double theta)
{
    switch (m.kind) {
    case MotionKind::rotation:
        if (rotation_off_fold(m))
            return rotation_arm_tip_on_layer_side(rotation_params(m), rotation_layer(m),
                                                  rotation_side(m), theta);
        return rotation_arm_tip(rotation_params(m), theta);
    case MotionKind::vertical:
        return v_box_front_corner(vertical_params(m), theta);
    case MotionKind::horizontal: {
        const HorizontalTranslationParams h = horizontal_params(m);
        return at(horizontal_translation_tip(h, theta), h.offset + h.width / 2);
    }
    case MotionKind::diagonal: {
        const StepFoldParams s = diagonal_step(m);
        const BasePatchPair wings = v_fold_wings(diagonal_v_fold(m), M_PI, theta);
        const Vec2 nose =
            s.run_ground * ground_dir(wings.opening) + s.run_backdrop * backdrop_dir(wings.opening);
        return wings.to_world(nose.x(), s.offset + s.width / 2, nose.y());
    }
    case MotionKind::stationary: {
        const FloatingLayerParams f = layer_params(m);
        const double anchor = m.p[5];
        const Vec2 along = anchor >= 0 ? ground_dir(theta) : backdrop_dir(theta);
        return at(Vec2(0, f.height) + std::abs(anchor) * along, f.offset + f.width / 2);
    }
    }
    return Vec3::Zero();
}

namespace {

// The rotation arm's points in the card frame at fold angle theta: O on its hinge, the wings'
// outer corners S (the arm's wing O-S-P) and S', R on the spine, the tip P.
struct ArmInCard {
    Vec3 O, S, Sb, R, P;
};

ArmInCard arm_in_card(const MotionMechanism& m, double theta)
{
    const RotationArmParams r = rotation_params(m);
    BasePatchPair host; // the central fold: the card frame
    host.opening = theta;
    if (rotation_off_fold(m))
        host = floating_layer_side(rotation_layer(m), rotation_side(m), theta);
    const RotationArmPoints a = rotation_arm_points(r, host.opening);
    auto world = [&](const Vec3& q) { return host.to_world(q.x(), r.offset + q.y(), q.z()); };
    return {world(Vec3::Zero()), world(a.S), world(a.Sb), world(a.R), world(a.P)};
}

} // namespace

Vec3 rotation_carried_point(const MotionMechanism& m, const Vec2& open, double theta)
{
    // The wing O-S-P is rigid: a point of its plane keeps its coordinates along S − O and P − O.
    // Open, the point is the one of the plane above `open` (the wing lies on the page there).
    const ArmInCard a = arm_in_card(m, M_PI);
    const Vec3 e1 = a.S - a.O, e2 = a.P - a.O, n = e1.cross(e2);
    if (!(std::abs(n.z()) > 1e-9 * n.norm()))
        return mechanism_point(m, theta); // the wing stands edge-on to the page: at its tip
    const Vec3 q(open.x(), open.y(),
                 a.O.z() - (n.x() * (open.x() - a.O.x()) + n.y() * (open.y() - a.O.y())) / n.z());
    Eigen::Matrix<double, 3, 2> basis;
    basis << e1, e2;
    const Vec2 c = basis.colPivHouseholderQr().solve(q - a.O);
    const ArmInCard b = arm_in_card(m, theta);
    return b.O + c.x() * (b.S - b.O) + c.y() * (b.P - b.O);
}

void mechanism_parts(const MotionMechanism& m, double theta, std::vector<MechanismPart>& out)
{
    const double d = theta / 2;
    const Vec2 g = ground_dir(theta), b = backdrop_dir(theta);
    PartWriter parts{out};
    switch (m.kind) {
    case MotionKind::rotation: {
        // O, S, R, S' and the arm's tip P (docs/MATH.md, Rotation). The arm's wing O-S-P is cut
        // along the spine O-R (R lies on S-P): O-S-R has x = α w sin δ ≥ 0, O-R-P x ≤ 0 in its
        // host's frame. Off the fold the host is a floating layer's side pair at θ/2 (docs/MATH.md,
        // A rotation arm on a floating layer's side): the layer's pieces come too, and the arm's
        // keep to no side of the fold's plane (its tip may swing across it).
        const bool off_fold = rotation_off_fold(m);
        if (off_fold)
            layer_parts(rotation_layer(m), theta, parts);
        const ArmInCard arm = arm_in_card(m, theta);
        const Vec3 &O = arm.O, &S = arm.S, &Sb = arm.Sb, &R = arm.R, &P = arm.P;
        parts.add(off_fold ? 0 : +1, {O, S, R});
        parts.add(off_fold ? 0 : -1, {O, R, P});
        parts.add(off_fold ? 0 : -1, {O, R, Sb});
        break;
    }
    case MotionKind::vertical: {
        // The walls FL, FR are rectangles: their tops are the feet plus F' − F. The top's back
        // corner is where the three top edges meet; both roots are kept (conservative). F' and
        // both roots lie on x = 0 (the section is symmetric about it), so each wall and each
        // top half keeps to its page's side.
        const VBoxFoldParams p = vertical_params(m);
        const double across = p.side * std::sin(p.wall_angle);
        const double along = p.side * std::cos(p.wall_angle);
        const Vec3 F(0, p.offset, 0);
        const Vec3 Sg = at(across * g, p.offset + along), Sb = at(across * b, p.offset + along);
        const Vec3 Ft = v_box_front_corner(p, theta);
        const Vec3 lift = Ft - F;
        parts.add(+1, {F, Sg, Sg + lift, Ft});
        parts.add(-1, {F, Sb, Sb + lift, Ft});
        const std::vector<Vec3> corner =
            trilaterate(Ft, Sg + lift, Sb + lift, 2 * along, p.side, p.side);
        std::vector<Vec3>& halfSg = parts.add(+1, {Ft, Sg + lift});
        halfSg.insert(halfSg.end(), corner.begin(), corner.end());
        std::vector<Vec3>& halfSb = parts.add(-1, {Ft, Sb + lift});
        halfSb.insert(halfSb.end(), corner.begin(), corner.end());
        break;
    }
    case MotionKind::horizontal: {
        // The step's riser A-C and tread D-C, and the extruding patch from the hinge to P = r
        // C/|C|. x of A = a sin δ, of D = −b sin δ, of C and P (a − b) sin δ (times r/|C| for P).
        const HorizontalTranslationParams h = horizontal_params(m);
        const Vec2 A = h.run_ground * g, D = h.run_backdrop * b, C = A + D;
        const Vec2 P = h.reach * C / C.norm();
        // With a ≥ b the tread crosses x = 0 at Q = D + (b/a)(C − D) = b(g + b) = (0, 2b cos δ):
        // it is cut there into a backdrop and a ground piece.
        const double y0 = h.offset, y1 = h.offset + h.width;
        auto strip = [&](const Vec2& p, const Vec2& q, int side) {
            parts.add(side, {at(p, y0), at(q, y0), at(q, y1), at(p, y1)});
        };
        if (h.run_ground >= h.run_backdrop) {
            const Vec2 Q(0, 2 * h.run_backdrop * std::cos(d));
            strip(A, C, +1);
            strip(D, Q, -1);
            strip(Q, C, +1);
            strip(Vec2(0, 0), P, +1);
        } else {
            strip(A, C, 0);
            strip(D, C, 0);
            strip(Vec2(0, 0), P, 0);
        }
        break;
    }
    case MotionKind::diagonal: {
        // The v-fold's wings O-A-P (x = X sin δ ≥ 0 at A, the tip on x = 0) and O-B-P, and the
        // step's riser and tread in the wings' pair (their nose may be on either side).
        const VFoldParams vf = diagonal_v_fold(m);
        const double X = vf.run * std::sin(vf.hinge_angle), Y = vf.run * std::cos(vf.hinge_angle);
        const Vec3 O(0, vf.offset, 0), tip = v_fold_tip(vf, M_PI, theta);
        parts.add(+1, {O, Vec3(X * std::sin(d), vf.offset + Y, X * std::cos(d)), tip});
        parts.add(-1, {O, Vec3(-X * std::sin(d), vf.offset + Y, X * std::cos(d)), tip});
        const StepFoldParams s = diagonal_step(m);
        const BasePatchPair wings = v_fold_wings(vf, M_PI, theta);
        const Vec2 A = s.run_ground * ground_dir(wings.opening);
        const Vec2 D = s.run_backdrop * backdrop_dir(wings.opening);
        const Vec2 C = A + D;
        const double y0 = s.offset, y1 = s.offset + s.width;
        parts.add(0, {wings.to_world(A.x(), y0, A.y()), wings.to_world(C.x(), y0, C.y()),
                      wings.to_world(C.x(), y1, C.y()), wings.to_world(A.x(), y1, A.y())});
        parts.add(0, {wings.to_world(D.x(), y0, D.y()), wings.to_world(C.x(), y0, C.y()),
                      wings.to_world(C.x(), y1, C.y()), wings.to_world(D.x(), y1, D.y())});
        break;
    }
    case MotionKind::stationary:
        layer_parts(layer_params(m), theta, parts);
        break;
    }
    out.resize(parts.count);
}

std::vector<MechanismPart> mechanism_parts(const MotionMechanism& m, double theta)
{
    std::vector<MechanismPart> parts;
    mechanism_parts(m, theta, parts);
    return parts;
}

std::vector<Vec3> mechanism_vertices(const MotionMechanism& m, double theta)
{
    std::vector<Vec3> v;
    for (const MechanismPart& part : mechanism_parts(m, theta))
        v.insert(v.end(), part.vertices.begin(), part.vertices.end());
    return v;
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

bool diagonal_wings_fit(const MotionMechanism& m, const CardParams& card)
{
    // The v-fold's two wings are one piece of the sheets, unfolded about their spine O–P: the
    // wing O-A-P (mechanism_parts' first piece) and its mirror across O–P. Across the spine the
    // piece spans twice A's distance from it; along it, the wing's shadow on O–P. The card is
    // the largest whose open sheet (W × 2D) fits the paper, so the piece, grown by a glue tab on
    // each side, must fit W × 2D one way or the other.
    if (m.kind != MotionKind::diagonal)
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

namespace {

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

Violation first_violation(const MotionMechanism& m, const CardParams& card)
{
    const double W = card.width, D = card.depth;
    for (int i = 0; i < parameter_count(m.kind); ++i)
        if (!std::isfinite(m.p[i]))
            return fail(parameter_info(m.kind, i).name, m.p[i], "finite");
    const double lo_angle = 5 * M_PI / 180, hi_angle = 85 * M_PI / 180;
    switch (m.kind) {
    case MotionKind::rotation: {
        const RotationArmParams r = rotation_params(m);
        if (!(r.spine >= shortest_crease() && r.spine <= W))
            return fail("spine", r.spine, "in [shortest glued crease, card width]");
        // The wing's width: a glue tab on its crease needs a patch that wide to sit on.
        if (!(r.run >= shortest_crease()))
            return fail("run", r.run, ">= the shortest glued crease");
        if (!(m.p[0] >= 0 && m.p[0] + r.spine <= W))
            return fail("offset", m.p[0], "in [0, card width - spine]");
        if (!rotation_off_fold(m)) {
            if (!(r.run > margin && r.run < D - margin))
                return fail("run", r.run, "in (1, card depth - 1)");
            if (!(r.arm > margin && r.arm <= std::min(r.spine * r.spine / r.run, D) * (1 - 1e-6)))
                return fail("arm", r.arm, "in (1, min(spine²/run, card depth)]");
            break;
        }
        // On a layer's side pair: the layer's supports and height are glued creases; the wings
        // reach the page beyond the support (D − s) and the support (the layer's height, which
        // rotation_layer_height keeps above Run and Arm).
        const FloatingLayerParams f = rotation_layer(m);
        if (!(f.support >= shortest_crease() && f.support < D - margin))
            return fail("hinge", m.p[4], "with |hinge| in [shortest glued crease, card depth - 1)");
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
            return fail("hinge", m.p[4], "with the layer's height under the closed card's top");
        if (!layer_strip_fits(f, card))
            return fail("hinge", m.p[4],
                        "with the layer's height, unfolded with its tabs, within the card's open "
                        "sheet (2 × depth)");
        break;
    }
    case MotionKind::vertical: {
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
        break;
    }
    case MotionKind::horizontal: {
        const HorizontalTranslationParams h = horizontal_params(m);
        if (!(h.width >= std::max(12.0, shortest_crease()) && h.offset >= 0 &&
              h.offset + h.width <= W))
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
        break;
    }
    case MotionKind::diagonal: {
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
        if (!(std::min({v.run, v.spine, s.width, s.run_ground, s.run_backdrop}) >=
              shortest_crease()))
            return fail("run", v.run,
                        "with spine, step_width and the step's runs >= the shortest glued crease");
        if (!(s.run_ground > margin && s.run_ground < room))
            return fail("run_ground", s.run_ground, "inside the v-fold's wing");
        if (!(s.run_backdrop > margin && s.run_backdrop < room))
            return fail("run_backdrop", s.run_backdrop, "inside the v-fold's wing");
        break;
    }
    case MotionKind::stationary: {
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
        if (!(std::abs(m.p[5]) <= f.support + f.overhang))
            return fail("anchor", m.p[5], "on the platform (|anchor| <= support + overhang)");
        if (!layer_strip_fits(f, card))
            return fail("support", f.support,
                        "with height and overhang, unfolded with its tabs, within the card's open "
                        "sheet (2 × depth)");
        break;
    }
    }
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

Result<std::vector<MechanismParts>> build_mechanism(Scaffold& scaffold, const BasePatchPair& host,
                                                    const MotionMechanism& m,
                                                    const std::string& name,
                                                    std::vector<FittedMechanism>& rows)
{
    Result<std::vector<MechanismParts>> out;
    auto take = [&](Result<MechanismParts> r, FittedMechanism row) {
        out.diagnostics.insert(out.diagnostics.end(), r.diagnostics.begin(), r.diagnostics.end());
        if (!r.ok) {
            out.ok = false;
            return false;
        }
        out.value.push_back(r.value);
        rows.push_back(std::move(row));
        return true;
    };
    FittedMechanism row;
    row.name = name;
    row.host = "central fold";
    switch (m.kind) {
    case MotionKind::rotation: {
        const RotationArmParams r = rotation_params(m);
        row.type = "rotation_arm";
        row.parameters = {{"offset", r.offset}, {"spine", r.spine}, {"run", r.run}, {"arm", r.arm}};
        if (!rotation_off_fold(m)) {
            take(add_rotation_arm(scaffold, host, r, name), row);
            break;
        }
        // Off the fold: the floating layer first (the host before what it carries), then the
        // arm on its side pair (docs/MATH.md, A rotation arm on a floating layer's side).
        const FloatingLayerParams f = rotation_layer(m);
        const FittedMechanism layer = layer_row(f, name + "_layer", row.host);
        if (!take(add_floating_layer(scaffold, host, f, layer.name), layer))
            break;
        const BasePatchPair side =
            out.value.back().offered.at(rotation_side(m) == LayerSide::ground ? 1 : 2);
        row.host = side.name;
        take(add_rotation_arm(scaffold, side, r, name), row);
        break;
    }
    case MotionKind::vertical: {
        const VBoxFoldParams v = vertical_params(m);
        row.type = "vertical_translation";
        row.parameters = {{"offset", v.offset},
                          {"side", v.side},
                          {"height", v.height},
                          {"wall_angle", v.wall_angle},
                          {"back", 0.0}};
        take(add_vertical_translation(scaffold, host, v, name), row);
        break;
    }
    case MotionKind::horizontal: {
        const HorizontalTranslationParams h = horizontal_params(m);
        row.type = "horizontal_translation";
        row.parameters = {{"offset", h.offset},
                          {"width", h.width},
                          {"run_ground", h.run_ground},
                          {"run_backdrop", h.run_backdrop},
                          {"reach", h.reach}};
        take(add_horizontal_translation(scaffold, host, h, name), row);
        break;
    }
    case MotionKind::diagonal: {
        const VFoldParams v = diagonal_v_fold(m);
        row.type = "v_fold";
        row.parameters = {{"offset", v.offset},
                          {"run", v.run},
                          {"hinge_angle", v.hinge_angle},
                          {"spine", v.spine},
                          {"spine_angle", v.spine_angle}};
        if (!take(add_v_fold(scaffold, host, v, name), row))
            break;
        const BasePatchPair wings = out.value.back().offered.at(0);
        const StepFoldParams s = diagonal_step(m);
        FittedMechanism step;
        step.type = "step_fold";
        step.name = name + "_step";
        step.host = wings.name;
        step.parameters = {{"offset", s.offset},
                           {"width", s.width},
                           {"run_ground", s.run_ground},
                           {"run_backdrop", s.run_backdrop}};
        take(add_step_fold(scaffold, wings, s, step.name), step);
        break;
    }
    case MotionKind::stationary: {
        const FloatingLayerParams f = layer_params(m);
        take(add_floating_layer(scaffold, host, f, name), layer_row(f, name, row.host));
        break;
    }
    }
    return out;
}

} // namespace popup::motion
