#include "mechanism_parts.hpp"

#include <algorithm>
#include <cmath>

#include "motion_kinematics.hpp"
#include "motion_parameters.hpp"

namespace popup::motion {

namespace {

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

} // namespace

void mechanism_parts(const MotionMechanism& m, double theta, std::vector<MechanismPart>& out)
{
    const double d = theta / 2;
    const Vec2 g = ground_dir(theta), b = backdrop_dir(theta);
    PartWriter parts{out};
    switch (m.kind()) {
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

} // namespace popup::motion
