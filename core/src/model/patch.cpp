#include "popup/model/patch.hpp"

#include <algorithm>
#include <cmath>

#include "../geometry/polygon_2d.hpp"

namespace popup {

namespace {
const char* const kRoleNames[] = {"ground", "backdrop", "support", "top",
                                  "front",  "back",     "tab",     "other"};
}

const char* to_string(PatchRole role)
{
    return kRoleNames[static_cast<int>(role)];
}

bool parse_patch_role(const std::string& name, PatchRole& role)
{
    for (int i = 0; i < 8; ++i) {
        if (name == kRoleNames[i]) {
            role = static_cast<PatchRole>(i);
            return true;
        }
    }
    return false;
}

double Patch::derive_frame()
{
    // Newell's normal follows the winding and is robust for non-convex loops.
    Vec3 n = Vec3::Zero();
    Vec3 mean = Vec3::Zero();
    for (size_t i = 0; i < outer.size(); ++i) {
        const Vec3& a = outer[i];
        const Vec3& b = outer[(i + 1) % outer.size()];
        n += Vec3((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
                  (a.x() - b.x()) * (a.y() + b.y()));
        mean += a;
    }
    if (outer.empty() || n.norm() == 0.0)
        return INFINITY;
    normal = n.normalized();
    origin = mean / double(outer.size());
    // u along the longest edge keeps the local frame stable under small edits.
    Vec3 longest = Vec3::Zero();
    for (size_t i = 0; i < outer.size(); ++i) {
        const Vec3 e = outer[(i + 1) % outer.size()] - outer[i];
        if (e.squaredNorm() > longest.squaredNorm())
            longest = e;
    }
    u = (longest - longest.dot(normal) * normal).normalized();
    v = normal.cross(u);
    double deviation = 0.0;
    auto measure = [&](const Loop3& loop) {
        for (const Vec3& p : loop)
            deviation = std::max(deviation, std::abs((p - origin).dot(normal)));
    };
    measure(outer);
    for (const Loop3& hole : holes)
        measure(hole);
    return deviation;
}

Vec2 Patch::to_local(const Vec3& x) const
{
    const Vec3 d = x - origin;
    return {d.dot(u), d.dot(v)};
}

Loop2 Patch::outer_local() const
{
    Loop2 out;
    for (const Vec3& p : outer)
        out.push_back(to_local(p));
    return out;
}

std::vector<Loop2> Patch::holes_local() const
{
    std::vector<Loop2> out;
    for (const Loop3& hole : holes) {
        Loop2 loop;
        for (const Vec3& p : hole)
            loop.push_back(to_local(p));
        out.push_back(loop);
    }
    return out;
}

namespace {
double signed_area(const Loop2& loop)
{
    double a = 0.0;
    for (size_t i = 0; i < loop.size(); ++i) {
        const Vec2& p = loop[i];
        const Vec2& q = loop[(i + 1) % loop.size()];
        a += p.x() * q.y() - q.x() * p.y();
    }
    return 0.5 * a;
}
} // namespace

double Patch::area() const
{
    double a = std::abs(signed_area(outer_local()));
    for (const Loop2& hole : holes_local())
        a -= std::abs(signed_area(hole));
    return a;
}

Vec3 Patch::centroid() const
{
    Vec3 c = Vec3::Zero();
    for (const Vec3& p : outer)
        c += p;
    return outer.empty() ? c : Vec3(c / double(outer.size()));
}

bool Patch::contains(const Vec3& x, double tol) const
{
    if (std::abs((x - origin).dot(normal)) > tol)
        return false;
    const Vec2 q = to_local(x);
    if (!point_in_polygon_or_near(outer_local(), q, tol))
        return false;
    for (const Loop2& hole : holes_local())
        if (point_in_polygon_or_near(hole, q, -tol))
            return false;
    return true;
}

std::string patch_subject(const Patch& patch)
{
    return "patch " + std::to_string(patch.id) +
           (patch.name.empty() ? "" : " (" + patch.name + ")");
}

} // namespace popup
