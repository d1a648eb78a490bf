#include "model_walls.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace popup {
namespace {

/// A flat wall across x: faces with |n · x| > 0.99 in neighbouring bins of x · p.
struct Wall {
    double area = 0;
    double position = 0; ///< area-weighted x · p
    double y_lo = 1e300, y_hi = -1e300;
};

/// The model's flat walls across `x`, inside its extent unless `at_ends` (then its two end planes
/// too), faces whose normal has the sign `sign` along x (0: either), binned by x · p (a
/// thousandth of the extent, neighbouring bins joined).
std::vector<Wall> flat_walls(const ModelMesh& model, const Vec3& x, const Vec3& y, int sign,
                             bool at_ends)
{
    double lo = 1e300, hi = -1e300;
    for (const Vec3& v : model.vertices) {
        lo = std::min(lo, v.dot(x));
        hi = std::max(hi, v.dot(x));
    }
    const double tolerance = 1e-3 * (hi - lo);
    std::map<long, Wall> bins; // position summed as a moment until joined
    for (const auto& t : model.triangles) {
        const Vec3& p0 = model.vertices[t[0]];
        const Vec3& p1 = model.vertices[t[1]];
        const Vec3& p2 = model.vertices[t[2]];
        const Vec3 c = (p1 - p0).cross(p2 - p0);
        const double twice = c.norm();
        if (!(twice > 0) || std::abs(c.dot(x)) < 0.99 * twice || c.dot(x) * sign < 0)
            continue;
        const double at = (p0 + p1 + p2).dot(x) / 3;
        if (!at_ends && (at < lo + 10 * tolerance || at > hi - 10 * tolerance))
            continue;
        Wall& bin = bins[std::lround((at - lo) / (2 * tolerance))];
        bin.area += 0.5 * twice;
        bin.position += 0.5 * twice * at;
        for (const Vec3* p : {&p0, &p1, &p2}) {
            bin.y_lo = std::min(bin.y_lo, p->dot(y));
            bin.y_hi = std::max(bin.y_hi, p->dot(y));
        }
    }
    // Neighbouring bins are one wall cut by the binning.
    std::vector<Wall> walls;
    for (auto it = bins.begin(); it != bins.end();) {
        Wall w;
        long last = it->first;
        while (it != bins.end() && it->first <= last + 1) {
            w.area += it->second.area;
            w.position += it->second.position;
            w.y_lo = std::min(w.y_lo, it->second.y_lo);
            w.y_hi = std::max(w.y_hi, it->second.y_hi);
            last = it->first;
            ++it;
        }
        w.position /= w.area;
        walls.push_back(w);
    }
    return walls;
}

} // namespace

std::vector<double> inner_walls(const ModelMesh& model, const Vec3& x, double min_area, int count)
{
    std::vector<Wall> walls = flat_walls(model, x, x.unitOrthogonal(), 0, false);
    walls.erase(std::remove_if(walls.begin(), walls.end(),
                               [&](const Wall& w) { return w.area < min_area; }),
                walls.end());
    std::stable_sort(walls.begin(), walls.end(),
                     [](const Wall& a, const Wall& b) { return a.area > b.area; });
    std::vector<double> out;
    for (size_t i = 0; i < walls.size() && int(i) < count; ++i)
        out.push_back(walls[i].position);
    return out;
}

std::vector<double> block_centres(const ModelMesh& model, const Vec3& x, const Vec3& y,
                                  double min_area, int count)
{
    double lo = 1e300, hi = -1e300;
    for (const Vec3& v : model.vertices) {
        lo = std::min(lo, v.dot(x));
        hi = std::max(hi, v.dot(x));
    }
    // The model's own ends count as walls too: a block may stand at its front or back.
    auto ends = [&](int sign) {
        std::vector<Wall> walls = flat_walls(model, x, y, sign, true);
        walls.erase(std::remove_if(walls.begin(), walls.end(),
                                   [&](const Wall& w) { return w.area < min_area; }),
                    walls.end());
        return walls;
    };
    const std::vector<Wall> fronts = ends(-1), backs = ends(+1);
    std::vector<std::pair<double, double>> centres; // (smaller wall's area, position)
    for (const Wall& f : fronts)
        for (const Wall& b : backs) {
            const double overlap = std::min(f.y_hi, b.y_hi) - std::max(f.y_lo, b.y_lo);
            const double shorter = std::min(f.y_hi - f.y_lo, b.y_hi - b.y_lo);
            if (b.position <= f.position || overlap < 0.5 * shorter)
                continue;
            centres.push_back({std::min(f.area, b.area), 0.5 * (f.position + b.position)});
        }
    std::stable_sort(centres.begin(), centres.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<double> out;
    const double apart = 0.05 * (hi - lo); // folds closer than this fit the same boxes
    for (const auto& c : centres) {
        const bool near = std::abs(c.second - 0.5 * (lo + hi)) < apart ||
                          std::any_of(out.begin(), out.end(),
                                      [&](double o) { return std::abs(o - c.second) < apart; });
        if (!near && int(out.size()) < count)
            out.push_back(c.second);
    }
    return out;
}

} // namespace popup
