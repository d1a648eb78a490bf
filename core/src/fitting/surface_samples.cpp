#include "popup/fitting/surface_samples.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace popup {

SurfaceSamples sample_surface(const ModelMesh& mesh, int count, std::uint64_t seed)
{
    SurfaceSamples out;
    const size_t n = mesh.triangles.size();
    std::vector<double> cumulative(n);
    std::vector<Vec3> normals(n);
    double total = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const auto& t = mesh.triangles[i];
        const Vec3 c = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                           .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
        const double a = 0.5 * c.norm();
        normals[i] = a > 0 ? Vec3(c.normalized()) : Vec3::UnitZ();
        total += a;
        cumulative[i] = total;
    }
    if (count <= 0 || !(total > 0))
        return out;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    out.points.reserve(count);
    out.normals.reserve(count);
    for (int i = 0; i < count; ++i) {
        // Stratified: one draw per equal slice of the area keeps the points even.
        const double target = (i + uniform(rng)) / count * total;
        size_t k =
            std::lower_bound(cumulative.begin(), cumulative.end(), target) - cumulative.begin();
        k = std::min(k, n - 1);
        while (k > 0 && cumulative[k] == cumulative[k - 1]) // skip zero-area triangles
            --k;
        const auto& t = mesh.triangles[k];
        // Uniform in the triangle: the square-root warp of two uniform numbers.
        const double r1 = std::sqrt(uniform(rng)), r2 = uniform(rng);
        const Vec3 p = (1 - r1) * mesh.vertices[t[0]] + r1 * (1 - r2) * mesh.vertices[t[1]] +
                       r1 * r2 * mesh.vertices[t[2]];
        out.points.push_back(p);
        out.normals.push_back(normals[k]);
    }
    out.spacing = std::sqrt(total / count);
    return out;
}

SurfaceSamples transformed(const SurfaceSamples& samples, const Eigen::Matrix4d& transform)
{
    SurfaceSamples out;
    const Mat3 linear = transform.topLeftCorner<3, 3>();
    const Vec3 shift = transform.topRightCorner<3, 1>();
    const double scale = std::cbrt(std::abs(linear.determinant()));
    const Mat3 rotation = linear / scale;
    out.points.reserve(samples.points.size());
    out.normals.reserve(samples.normals.size());
    for (const Vec3& p : samples.points)
        out.points.push_back(linear * p + shift);
    for (const Vec3& n : samples.normals)
        out.normals.push_back(rotation * n);
    out.spacing = samples.spacing * scale;
    return out;
}

} // namespace popup
