#include "fitting/synthetic_models.hpp"

#include <cmath>

namespace popup::testing {
namespace {

double cross2(const Vec2& a, const Vec2& b, const Vec2& c)
{
    return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

/// Ear clipping of a simple counter-clockwise polygon.
std::vector<std::array<int, 3>> triangulate(const std::vector<Vec2>& p)
{
    std::vector<int> left(p.size());
    for (size_t i = 0; i < p.size(); ++i)
        left[i] = int(i);
    std::vector<std::array<int, 3>> out;
    while (left.size() > 3) {
        bool cut = false;
        for (size_t i = 0; i < left.size() && !cut; ++i) {
            const int a = left[(i + left.size() - 1) % left.size()], b = left[i],
                      c = left[(i + 1) % left.size()];
            if (cross2(p[a], p[b], p[c]) <= 1e-12)
                continue;
            bool empty = true;
            for (int k : left)
                if (k != a && k != b && k != c && cross2(p[a], p[b], p[k]) >= 0 &&
                    cross2(p[b], p[c], p[k]) >= 0 && cross2(p[c], p[a], p[k]) >= 0)
                    empty = false;
            if (!empty)
                continue;
            out.push_back({a, b, c});
            left.erase(left.begin() + long(i));
            cut = true;
        }
        if (!cut)
            break;
    }
    if (left.size() == 3)
        out.push_back({left[0], left[1], left[2]});
    return out;
}

double signed_volume(const ModelMesh& m)
{
    double v = 0;
    for (const auto& t : m.triangles)
        v += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]])) / 6;
    return v;
}

/// Extrudes polygon (u, v) along w; `at(u, v, w)` places a point.
template <class At> ModelMesh extrude(const std::vector<Vec2>& poly, double w0, double w1, At at)
{
    ModelMesh m;
    const int n = int(poly.size());
    for (double w : {w0, w1})
        for (const Vec2& q : poly)
            m.vertices.push_back(at(q.x(), q.y(), w));
    for (const auto& t : triangulate(poly)) {
        m.triangles.push_back({t[0], t[2], t[1]});
        m.triangles.push_back({n + t[0], n + t[1], n + t[2]});
    }
    for (int i = 0; i < n; ++i) {
        const int j = (i + 1) % n;
        m.triangles.push_back({i, j, n + j});
        m.triangles.push_back({i, n + j, n + i});
    }
    if (signed_volume(m) < 0)
        for (auto& t : m.triangles)
            std::swap(t[1], t[2]);
    return m;
}

} // namespace

ModelMesh extrude_section(const std::vector<Vec2>& s, double y0, double y1)
{
    return extrude(s, y0, y1, [](double x, double z, double y) { return Vec3(x, y, z); });
}

ModelMesh extrude_elevation(const std::vector<Vec2>& e, double half_x)
{
    return extrude(e, -half_x, half_x, [](double y, double z, double x) { return Vec3(x, y, z); });
}

ModelMesh box_mesh(const Vec3& lo, const Vec3& hi)
{
    return extrude_section({{lo.x(), lo.z()}, {hi.x(), lo.z()}, {hi.x(), hi.z()}, {lo.x(), hi.z()}},
                           lo.y(), hi.y());
}

ModelMesh join(const std::vector<ModelMesh>& parts)
{
    ModelMesh m;
    for (const ModelMesh& p : parts) {
        const int base = int(m.vertices.size());
        m.vertices.insert(m.vertices.end(), p.vertices.begin(), p.vertices.end());
        for (const auto& t : p.triangles)
            m.triangles.push_back({base + t[0], base + t[1], base + t[2]});
    }
    return m;
}

ModelMesh subdivided(const ModelMesh& mesh, int levels)
{
    ModelMesh m = mesh;
    for (int l = 0; l < levels; ++l) {
        ModelMesh next;
        next.vertices = m.vertices;
        for (const auto& t : m.triangles) {
            const int a = t[0], b = t[1], c = t[2];
            const int ab = int(next.vertices.size());
            next.vertices.push_back(0.5 * (m.vertices[a] + m.vertices[b]));
            next.vertices.push_back(0.5 * (m.vertices[b] + m.vertices[c]));
            next.vertices.push_back(0.5 * (m.vertices[c] + m.vertices[a]));
            const int bc = ab + 1, ca = ab + 2;
            next.triangles.push_back({a, ab, ca});
            next.triangles.push_back({ab, b, bc});
            next.triangles.push_back({ca, bc, c});
            next.triangles.push_back({ab, bc, ca});
        }
        m = next;
    }
    return m;
}

ModelMesh tessellated(const ModelMesh& mesh, int vertices)
{
    const double per_triangle =
        double(vertices) / double(std::max<size_t>(1, mesh.triangles.size()));
    int n = 1;
    while ((n + 2) * (n + 3) / 2.0 <= per_triangle)
        ++n;
    ModelMesh m;
    m.source = mesh.source;
    for (const auto& t : mesh.triangles) {
        const Vec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
        const int base = int(m.vertices.size());
        auto index = [&](int i, int j) { return base + i * (n + 1) - i * (i - 1) / 2 + j; };
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n - i; ++j)
                m.vertices.push_back(a + (b - a) * (double(j) / n) + (c - a) * (double(i) / n));
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n - i; ++j) {
                m.triangles.push_back({index(i, j), index(i, j + 1), index(i + 1, j)});
                if (j + 1 < n - i)
                    m.triangles.push_back({index(i, j + 1), index(i + 1, j + 1), index(i + 1, j)});
            }
    }
    return m;
}

ModelMesh moved(const ModelMesh& mesh, const Mat3& rotation, double scale, const Vec3& shift)
{
    ModelMesh m = mesh;
    for (Vec3& v : m.vertices)
        v = scale * (rotation * v) + shift;
    return m;
}

ModelMesh cuboid_model()
{
    ModelMesh m = box_mesh({-20, 0, 0}, {20, 120, 30});
    m.source = "cuboid";
    return m;
}

ModelMesh house_model()
{
    ModelMesh m = extrude_section({{-30, 0}, {30, 0}, {30, 24}, {0, 42}, {-30, 24}}, 0, 100);
    m.source = "house";
    return m;
}

ModelMesh truck_model()
{
    ModelMesh m = join({box_mesh({-20, 0, 0}, {20, 140, 14}), box_mesh({-20, 0, 14}, {20, 80, 50}),
                        box_mesh({-20, 96, 14}, {20, 132, 38})});
    m.source = "truck";
    return m;
}

ModelMesh tent_model()
{
    ModelMesh m = extrude_section({{-30, 0}, {30, 0}, {0, 36}}, 0, 110);
    m.source = "tent";
    return m;
}

ModelMesh annexed_model()
{
    ModelMesh m = join({box_mesh({-20, 0, 0}, {20, 100, 30}), box_mesh({20, 20, 0}, {35, 70, 12}),
                        box_mesh({-35, 20, 0}, {-20, 70, 12})});
    m.source = "annexed box";
    return m;
}

ModelMesh l_plan_model()
{
    // The plan drawn in (x, -y) and extruded 30 along the section's normal, then turned
    // (x, y, z) -> (x, -z, y): a proper rotation, so the faces stay outward.
    const ModelMesh flat =
        extrude_section({{0, 0}, {0, -50}, {20, -50}, {20, -20}, {60, -20}, {60, 0}}, 0, 30);
    Mat3 turn;
    turn << 1, 0, 0, 0, 0, -1, 0, 1, 0;
    ModelMesh m = moved(flat, turn, 1.0, Vec3::Zero());
    m.source = "L plan";
    return m;
}
ModelMesh l_building_model()
{
    ModelMesh m = extrude_elevation({{0, 0}, {100, 0}, {100, 24}, {30, 24}, {30, 60}, {0, 60}}, 20);
    m.source = "L building";
    return m;
}

ModelMesh sphere_mesh(const Vec3& centre, double radius, int segments, int rings)
{
    ModelMesh m;
    m.vertices.push_back(centre + Vec3(0, 0, -radius));
    for (int r = 1; r < rings; ++r) {
        const double phi = M_PI * r / rings - M_PI / 2;
        for (int k = 0; k < segments; ++k) {
            const double theta = 2 * M_PI * k / segments;
            m.vertices.push_back(centre + radius * Vec3(std::cos(phi) * std::cos(theta),
                                                        std::cos(phi) * std::sin(theta),
                                                        std::sin(phi)));
        }
    }
    m.vertices.push_back(centre + Vec3(0, 0, radius));
    const int top = int(m.vertices.size()) - 1;
    auto at = [&](int r, int k) { return 1 + (r - 1) * segments + (k % segments); };
    for (int k = 0; k < segments; ++k) {
        m.triangles.push_back({0, at(1, k + 1), at(1, k)});
        m.triangles.push_back({top, at(rings - 1, k), at(rings - 1, k + 1)});
        for (int r = 1; r + 1 < rings; ++r) {
            m.triangles.push_back({at(r, k), at(r, k + 1), at(r + 1, k + 1)});
            m.triangles.push_back({at(r, k), at(r + 1, k + 1), at(r + 1, k)});
        }
    }
    return m;
}

ModelMesh cylinder_mesh(const Vec3& from, const Vec3& to, double radius, int segments)
{
    std::vector<Vec2> circle;
    for (int k = 0; k < segments; ++k)
        circle.push_back(
            radius * Vec2(std::cos(2 * M_PI * k / segments), std::sin(2 * M_PI * k / segments)));
    const double length = (to - from).norm();
    ModelMesh m = extrude_section(circle, 0, length); // axis along y
    const Vec3 axis = (to - from) / length;
    const Mat3 turn = Eigen::Quaterniond::FromTwoVectors(Vec3::UnitY(), axis).toRotationMatrix();
    return moved(m, turn, 1.0, from);
}

ModelMesh figure_model()
{
    ModelMesh m = join(
        {sphere_mesh({0, 0, 62}, 14), cylinder_mesh({0, 0, 20}, {0, 0, 50}, 12),
         cylinder_mesh({0, -8, 0}, {0, -8, 22}, 5), cylinder_mesh({0, 8, 0}, {0, 8, 22}, 5),
         cylinder_mesh({0, -12, 46}, {0, -34, 30}, 4), cylinder_mesh({0, 12, 46}, {0, 34, 30}, 4)});
    m.source = "figure";
    return m;
}

ModelMesh blob_model()
{
    ModelMesh m = sphere_mesh({0, 0, 0}, 1.0, 48, 24);
    for (Vec3& v : m.vertices)
        v = Vec3(30 * v.x(), 50 * v.y(), 20 * v.z() + 20);
    m.source = "blob";
    return m;
}

} // namespace popup::testing
