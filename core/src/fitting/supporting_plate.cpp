#include "popup/fitting/supporting_plate.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace popup {
namespace {

constexpr double kFlatUp = 0.985; ///< cos 10°: a face this close to facing up is flat

/// Two unit directions across `up` along which the model's footprint box is smallest (a turned
/// slab's box would otherwise count corners it does not have).
std::pair<Vec3, Vec3> footprint_axes(const ModelMesh& model, const Vec3& up)
{
    Vec3 e1 = up.unitOrthogonal();
    const Vec3 e2 = up.cross(e1);
    double best = 1e300;
    std::pair<Vec3, Vec3> axes{e1, e2};
    for (int k = 0; k < 18; ++k) {
        const double a = k * M_PI / 36.0;
        const Vec3 u = std::cos(a) * e1 + std::sin(a) * e2, v = up.cross(u);
        Eigen::AlignedBox2d box;
        for (const Vec3& p : model.vertices)
            box.extend(Vec2(p.dot(u), p.dot(v)));
        if (box.volume() < best) {
            best = box.volume();
            axes = {u, v};
        }
    }
    return axes;
}

/// Footprint box area, along `axes`, of the vertices higher than `above` along `up`.
double footprint(const ModelMesh& model, const Vec3& up, const std::pair<Vec3, Vec3>& axes,
                 double above)
{
    Eigen::AlignedBox2d box;
    for (const Vec3& p : model.vertices)
        if (p.dot(up) > above)
            box.extend(Vec2(p.dot(axes.first), p.dot(axes.second)));
    return box.isEmpty() ? 0.0 : box.volume();
}

} // namespace

std::optional<SupportingPlate> supporting_plate(const ModelMesh& model, const Vec3& up_in)
{
    const Vec3 up = up_in.normalized();
    double bottom = 1e300, top = -1e300;
    for (const Vec3& p : model.vertices) {
        bottom = std::min(bottom, p.dot(up));
        top = std::max(top, p.dot(up));
    }
    const double height = top - bottom;
    if (!(height > 0))
        return std::nullopt;
    // Flat upward-facing area per level, levels a 400th of the height apart, in the lowest
    // quarter of the height.
    const double bin = height / 400.0;
    std::map<long, double> area_at, moment_at; // area and area-weighted level per bin
    for (const auto& t : model.triangles) {
        const Vec3 &a = model.vertices[t[0]], &b = model.vertices[t[1]], &c = model.vertices[t[2]];
        const Vec3 n = (b - a).cross(c - a);
        const double area = 0.5 * n.norm();
        if (!(area > 0) || n.dot(up) < kFlatUp * 2 * area)
            continue;
        const double level = (a + b + c).dot(up) / 3.0;
        if (level - bottom <= 0.25 * height) {
            const long at = std::lround((level - bottom) / bin);
            area_at[at] += area;
            moment_at[at] += area * level;
        }
    }
    if (area_at.empty())
        return std::nullopt;
    const auto widest = std::max_element(area_at.begin(), area_at.end(),
                                         [](auto& x, auto& y) { return x.second < y.second; });
    SupportingPlate plate;
    plate.up = up;
    // The faces' own level, not the bin's: the card's page is the plate's top exactly.
    plate.top = moment_at[widest->first] / widest->second;
    plate.thickness = plate.top - bottom;
    plate.top_area = widest->second;
    const auto axes = footprint_axes(model, up);
    const double whole = footprint(model, up, axes, -1e300);
    const double standing = footprint(model, up, axes, plate.top + 1e-3 * height);
    const double rise = top - plate.top;
    if (plate.thickness > 0.25 * height || plate.top_area < whole / 3.0 || standing <= 0 ||
        standing > 0.7 * whole || rise < 2.0 * plate.thickness)
        return std::nullopt;
    return plate;
}

ModelMesh above_plate(const ModelMesh& model, const SupportingPlate& plate)
{
    double bottom = 1e300, top = -1e300;
    for (const Vec3& p : model.vertices) {
        bottom = std::min(bottom, p.dot(plate.up));
        top = std::max(top, p.dot(plate.up));
    }
    const double level = plate.top + 1e-3 * (top - bottom);
    ModelMesh out = model;
    out.vertices.clear();
    out.colours.clear();
    out.uvs.clear();
    out.triangles.clear();
    std::vector<int> kept(model.vertices.size(), -1);
    auto keep = [&](int v) {
        if (kept[size_t(v)] < 0) {
            kept[size_t(v)] = int(out.vertices.size());
            out.vertices.push_back(model.vertices[size_t(v)]);
            if (!model.colours.empty())
                out.colours.push_back(model.colours[size_t(v)]);
            if (!model.uvs.empty())
                out.uvs.push_back(model.uvs[size_t(v)]);
        }
        return kept[size_t(v)];
    };
    for (const auto& t : model.triangles) {
        double highest = -1e300;
        for (int k = 0; k < 3; ++k)
            highest = std::max(highest, model.vertices[size_t(t[k])].dot(plate.up));
        if (highest > level)
            out.triangles.push_back({keep(t[0]), keep(t[1]), keep(t[2])});
    }
    return out;
}

SurfaceSamples samples_above(const SupportingPlate& plate, const SurfaceSamples& samples)
{
    SurfaceSamples out;
    out.spacing = samples.spacing;
    const double level =
        plate.top + std::max(1e-3 * plate.thickness, 1e-9 * (std::abs(plate.top) + 1.0));
    for (size_t i = 0; i < samples.points.size(); ++i)
        if (samples.points[i].dot(plate.up) > level) {
            out.points.push_back(samples.points[i]);
            out.normals.push_back(samples.normals[i]);
        }
    return out;
}

} // namespace popup
