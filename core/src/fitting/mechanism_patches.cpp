#include "popup/fitting/mechanism_patches.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "popup/mechanisms/tent_fold.hpp"

namespace popup {
namespace {

double distance_to_segment(const Vec3& q, const Vec3& a, const Vec3& b)
{
    const Vec3 d = b - a;
    const double t = std::clamp((q - a).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
    return (a + t * d - q).norm();
}

/// Distance to a convex planar polygon: to its plane where q lies over it, else to its outline.
double distance_to_polygon(const Vec3& q, const HostPolygon& poly)
{
    const size_t m = poly.size();
    Vec3 n = Vec3::Zero(); // Newell: twice the area, along the normal of the vertex order
    double edge = 1e300;
    for (size_t i = 0; i < m; ++i) {
        n += poly[i].cross(poly[(i + 1) % m]);
        edge = std::min(edge, distance_to_segment(q, poly[i], poly[(i + 1) % m]));
    }
    if (n.norm() < 1e-300)
        return edge;
    n.normalize();
    const double off = (q - poly[0]).dot(n);
    const Vec3 p = q - off * n;
    for (size_t i = 0; i < m; ++i)
        if ((poly[(i + 1) % m] - poly[i]).cross(p - poly[i]).dot(n) < 0)
            return edge;
    return std::abs(off);
}

/// A rectangle from y0 to y1 along the hinge over the section segment (x, z) from u to v.
HostPolygon along_hinge(const Vec2& u, const Vec2& v, double y0, double y1)
{
    return {{u.x(), y0, u.y()}, {u.x(), y1, u.y()}, {v.x(), y1, v.y()}, {v.x(), y0, v.y()}};
}

std::vector<HostPolygon> box_patches(const BoxFoldParams& q)
{
    // At 180° the box is x in [−b, g], z in [0, c]: C, L, R upright, TG and TB on top.
    const double y0 = q.offset, y1 = q.offset + q.width;
    const double g = q.depth_ground, b = q.depth_backdrop, c = q.height;
    std::vector<HostPolygon> out = {
        along_hinge({0, 0}, {0, c}, y0, y1), along_hinge({g, 0}, {g, c}, y0, y1),
        along_hinge({-b, 0}, {-b, c}, y0, y1), along_hinge({0, c}, {g, c}, y0, y1),
        along_hinge({-b, c}, {0, c}, y0, y1)};
    auto end = [&](double y) { return HostPolygon{{-b, y, 0}, {g, y, 0}, {g, y, c}, {-b, y, c}}; };
    if (q.front)
        out.push_back(end(y0));
    if (q.back)
        out.push_back(end(y1));
    return out;
}

std::vector<HostPolygon> tent_patches(const TentFoldParams& q)
{
    const Vec2 A(q.foot, 0), D(-q.foot_backdrop, 0), C = tent_apex(q, M_PI);
    return {along_hinge(A, C, q.offset, q.offset + q.width),
            along_hinge(C, D, q.offset, q.offset + q.width)};
}

std::vector<HostPolygon> v_fold_patches(const VFoldParams& q)
{
    const double reach = q.run * std::sin(q.hinge_angle), along = q.run * std::cos(q.hinge_angle);
    const Vec3 O(0, q.offset, 0), A(reach, q.offset + along, 0), B(-reach, q.offset + along, 0);
    const Vec3 P(0, q.offset + q.spine * std::cos(q.spine_angle),
                 q.spine * std::sin(q.spine_angle));
    return {{O, A, P}, {O, P, B}};
}

std::vector<HostPolygon> step_patches(const StepFoldParams& q, const PrismHost& host)
{
    // At 90° a rectangle: the riser stands `page` out from the wall, the tread `wall` up it.
    const bool page_is_ground = host.part != "side_backdrop";
    const double page = page_is_ground ? q.run_ground : q.run_backdrop;
    const double wall = page_is_ground ? q.run_backdrop : q.run_ground;
    const double y0 = q.offset, y1 = q.offset + q.width;
    return {along_hinge({page, 0}, {page, wall}, y0, y1),
            along_hinge({0, wall}, {page, wall}, y0, y1)};
}

} // namespace

std::vector<HostPolygon> design_patches(const DesignedMechanism& m, const PrismHost& host)
{
    switch (m.kind) {
    case MechanismKind::box_fold:
        return box_patches(m.as<BoxFoldParams>());
    case MechanismKind::tent_fold:
        return tent_patches(m.as<TentFoldParams>());
    case MechanismKind::v_fold:
        return v_fold_patches(m.as<VFoldParams>());
    case MechanismKind::step_fold:
        return step_patches(m.as<StepFoldParams>(), host);
    default:
        throw std::invalid_argument("design_patches: a mapped mechanism is a box, step, tent or "
                                    "v-fold, not a " +
                                    catalogue_entry(m.kind).title);
    }
}

double distance_to_patches(const Vec3& q, const std::vector<HostPolygon>& patches)
{
    double nearest = 1e300;
    for (const HostPolygon& p : patches)
        nearest = std::min(nearest, distance_to_polygon(q, p));
    return nearest;
}

Vec3 host_coordinates(const PrismHost& host, const Vec3& p)
{
    const Vec3 q = p - host.origin;
    return {q.dot(host.across), q.dot(host.axis), q.dot(host.up)};
}

} // namespace popup
