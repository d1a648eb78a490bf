#include "outer_surface.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace popup {

OuterSurface outer_surface(const OccupancyGrid& volume, const SurfaceSamples& samples)
{
    OuterSurface out;
    out.samples = samples;
    out.inner.assign(samples.points.size(), false);
    const double step = 2.0 * volume.cell();
    for (size_t i = 0; i < samples.points.size(); ++i) {
        const Vec3& p = samples.points[i];
        Vec3& n = out.samples.normals[i];
        const bool ahead = volume.solid_at(p + step * n), behind = volume.solid_at(p - step * n);
        if (ahead && behind) {
            out.inner[i] = true;
            ++out.inner_count;
        } else if (ahead) {
            n = -n;
            ++out.turned;
        }
    }
    return out;
}

SurfaceSamples outer_only(const OuterSurface& surface)
{
    if (surface.inner_count == int(surface.samples.points.size()))
        return surface.samples;
    SurfaceSamples out;
    out.spacing = surface.samples.spacing;
    for (size_t i = 0; i < surface.samples.points.size(); ++i)
        if (!surface.inner[i]) {
            out.points.push_back(surface.samples.points[i]);
            out.normals.push_back(surface.samples.normals[i]);
        }
    return out;
}

namespace {

/// Triangles joined across edges that exactly two of them share, labelled by component; and
/// per component whether every edge of it is shared by exactly two triangles (closed).
struct Components {
    std::vector<int> of;      ///< per triangle
    std::vector<bool> closed; ///< per component
};

int root(std::vector<int>& parent, int i)
{
    while (parent[size_t(i)] != i)
        i = parent[size_t(i)] = parent[size_t(parent[size_t(i)])];
    return i;
}

Components manifold_components(const ModelMesh& model)
{
    const size_t n = model.triangles.size();
    // Every edge (its two vertices, lower first) with its triangle, sorted: the triangles
    // sharing an edge are a run, in triangle order.
    std::vector<std::pair<std::uint64_t, int>> edges;
    edges.reserve(3 * n);
    for (size_t t = 0; t < n; ++t)
        for (int k = 0; k < 3; ++k) {
            const auto u = std::uint32_t(model.triangles[t][k]);
            const auto v = std::uint32_t(model.triangles[t][(k + 1) % 3]);
            edges.push_back({(std::uint64_t(std::min(u, v)) << 32) | std::max(u, v), int(t)});
        }
    std::sort(edges.begin(), edges.end());
    std::vector<std::pair<size_t, size_t>> runs; // [first, past the last) per edge
    for (size_t b = 0; b < edges.size();) {
        size_t e = b + 1;
        while (e < edges.size() && edges[e].first == edges[b].first)
            ++e;
        runs.push_back({b, e});
        b = e;
    }
    std::vector<int> parent(n);
    for (size_t t = 0; t < n; ++t)
        parent[t] = int(t);
    for (const auto& [b, e] : runs)
        if (e - b == 2)
            parent[size_t(root(parent, edges[b].second))] = root(parent, edges[b + 1].second);
    // Labels in the order of each component's first triangle (whatever its root).
    Components c;
    c.of.resize(n);
    std::vector<int> label(n, -1);
    int labels = 0;
    for (size_t t = 0; t < n; ++t) {
        int& l = label[size_t(root(parent, int(t)))];
        if (l < 0)
            l = labels++;
        c.of[t] = l;
    }
    c.closed.assign(size_t(labels), true);
    for (const auto& [b, e] : runs)
        if (e - b != 2)
            for (size_t k = b; k < e; ++k)
                c.closed[size_t(c.of[size_t(edges[k].second)])] = false;
    return c;
}

} // namespace

ModelMesh faces_turned_out(const ModelMesh& model, const OccupancyGrid& volume, int& turned)
{
    ModelMesh out = model;
    turned = 0;
    const Components parts = manifold_components(model);
    // A closed part bounds its own volume: the sign of that volume says its winding, whatever
    // touches it (the divergence theorem, about the part's first vertex to keep it exact).
    std::vector<double> signed_volume(parts.closed.size(), 0.0);
    std::vector<Vec3> origin(parts.closed.size(), Vec3::Constant(std::nan("")));
    for (size_t t = 0; t < model.triangles.size(); ++t) {
        const auto& f = model.triangles[t];
        Vec3& o = origin[size_t(parts.of[t])];
        if (std::isnan(o.x()))
            o = model.vertices[size_t(f[0])];
        const Vec3 a = model.vertices[size_t(f[0])] - o, b = model.vertices[size_t(f[1])] - o,
                   c = model.vertices[size_t(f[2])] - o;
        signed_volume[size_t(parts.of[t])] += a.dot(b.cross(c)) / 6.0;
    }
    // An open part (a sheet, a shell with holes) has no volume of its own: the model's volume
    // says which side of each face is out.
    const double step = 2.0 * volume.cell();
    for (size_t t = 0; t < out.triangles.size(); ++t) {
        auto& f = out.triangles[t];
        const int part = parts.of[t];
        bool turn = false;
        if (parts.closed[size_t(part)]) {
            turn = signed_volume[size_t(part)] < 0;
        } else {
            const Vec3 &a = model.vertices[size_t(f[0])], &b = model.vertices[size_t(f[1])],
                       &c = model.vertices[size_t(f[2])];
            const Vec3 normal = (b - a).cross(c - a);
            if (normal.norm() > 0) {
                const Vec3 centre = (a + b + c) / 3.0, n = normal.normalized();
                turn = volume.solid_at(centre + step * n) && !volume.solid_at(centre - step * n);
            }
        }
        if (turn) {
            std::swap(f[1], f[2]);
            ++turned;
        }
    }
    return out;
}

} // namespace popup
