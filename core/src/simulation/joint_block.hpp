#pragma once
// Internal: the rows one joint between two bodies adds to the fold's least-squares problem, and
// their blocks of the Jacobian with respect to the two bodies' motions (rotation parts scaled by
// the model size, so every column is in mm; docs/MATH.md, Solver and Slits). A hinge end gives
// three rows (its copies on both bodies coincide), a slit end one (it stays in the plane of the
// body passing through). Written once for the dense and the sparse normal equations and the
// Jacobian of the rank test; inline, as the assembly runs at every Newton step.
#include <Eigen/Core>

#include "body_graph.hpp"
#include "body_pose.hpp"

namespace popup {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;

/// Cross-product matrix: skew(v) x = v × x.
inline Mat3 skew(const Vec3& v)
{
    Mat3 m;
    m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
    return m;
}

/// Design-state point x of a body with design centre `center`, carried by its pose.
inline Vec3 place(const BodyPose& pose, const Vec3& center, const Vec3& x)
{
    return pose.rotation * (x - center) + pose.position;
}

/// The three rows of one hinge end: r = (x as carried by body a) - (x as carried by body b).
/// With a and b the end's arms from the bodies' centres over the model size, the Jacobian
/// blocks are Ja = [-[a]x, I] and Jb = [[b]x, -I].
struct HingeEndRows {
    Vec3 residual;
    Vec3 a;
    Vec3 b;

    Eigen::Matrix<double, 3, 6> jacobian_a() const
    {
        Eigen::Matrix<double, 3, 6> J;
        J << -skew(a), Mat3::Identity();
        return J;
    }
    Eigen::Matrix<double, 3, 6> jacobian_b() const
    {
        Eigen::Matrix<double, 3, 6> J;
        J << skew(b), -Mat3::Identity();
        return J;
    }
};

inline HingeEndRows hinge_end_rows(const Joint& joint, const Vec3& x, const Configuration& q,
                                   const BodyGraph& g, double size)
{
    const Vec3 arm_a = q[joint.body_a].rotation * (x - g.center[joint.body_a]);
    const Vec3 arm_b = q[joint.body_b].rotation * (x - g.center[joint.body_b]);
    HingeEndRows rows;
    rows.residual = (arm_a + q[joint.body_a].position) - (arm_b + q[joint.body_b].position);
    rows.a = arm_a / size;
    rows.b = arm_b / size;
    return rows;
}

/// Signed distance of a slit end from the plane of the body passing through, and its gradient
/// with respect to both bodies' motions (its Jacobian rows, transposed).
struct SlitRow {
    double distance;
    Vec6 through;
    Vec6 cut;
};

inline SlitRow slit_row(const SlitJoint& sl, int e, const Configuration& q, const BodyGraph& g,
                        double size)
{
    const BodyPose& t = q[sl.body_through];
    const BodyPose& c = q[sl.body_cut];
    const Vec3 n = t.rotation * sl.plane_normal;
    const Vec3 on_plane = place(t, g.center[sl.body_through], sl.plane_point);
    const Vec3 arm = c.rotation * (sl.ends[e] - g.center[sl.body_cut]);
    const Vec3 end = arm + c.position;
    SlitRow r;
    r.distance = n.dot(end - on_plane);
    r.through << n.cross(end - t.position) / size, -n;
    r.cut << arm.cross(n) / size, n;
    return r;
}

// Normal equations: a joint's rows add JᵀJ and Jᵀr blocks for its two bodies, side 0 (hinge
// body a, slit body passing through) and side 1 (body b, body cut). A base body has no
// unknowns and takes none. `to` is the assembly: to.add(i, j, block) adds Jᵢᵀ Jⱼ where the
// unknowns of sides i and j meet, to.add(i, vector) adds Jᵢᵀ r to the right-hand side.

/// One hinge end's terms; with Ja and Jb as above the products reduce to 3x3 terms.
template <class Assembly>
void add_normal_terms(const HingeEndRows& rows, bool free_a, bool free_b, Assembly& to)
{
    const Vec3& a = rows.a;
    const Vec3& b = rows.b;
    const Vec3& r = rows.residual;
    const Mat3 I = Mat3::Identity();
    if (free_a) {
        const Mat3 Sa = -skew(a);
        Mat6 aa;
        aa << a.squaredNorm() * I - a * a.transpose(), Sa.transpose(), Sa, I;
        Vec6 ga;
        ga << a.cross(r), r;
        to.add(0, 0, aa);
        to.add(0, ga);
    }
    if (free_b) {
        const Mat3 Sb = skew(b);
        Mat6 bb;
        bb << b.squaredNorm() * I - b * b.transpose(), -Sb.transpose(), -Sb, I;
        Vec6 gb;
        gb << -b.cross(r), -r;
        to.add(1, 1, bb);
        to.add(1, gb);
    }
    if (free_a && free_b) {
        // Jaᵀ Jb = [[a]x[b]x, -[a]x; [b]x, -I] and its transpose.
        Mat6 ab;
        ab << skew(a) * skew(b), -skew(a), skew(b), -I;
        to.add(0, 1, ab);
        to.add(1, 0, ab.transpose());
    }
}

/// One slit end's terms.
template <class Assembly>
void add_normal_terms(const SlitRow& row, bool free_through, bool free_cut, Assembly& to)
{
    if (free_through) {
        to.add(0, 0, row.through * row.through.transpose());
        to.add(0, row.through * row.distance);
    }
    if (free_cut) {
        to.add(1, 1, row.cut * row.cut.transpose());
        to.add(1, row.cut * row.distance);
    }
    if (free_through && free_cut) {
        const Mat6 tc = row.through * row.cut.transpose();
        to.add(0, 1, tc);
        to.add(1, 0, tc.transpose());
    }
}

} // namespace popup
