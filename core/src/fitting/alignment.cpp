#include "popup/fitting/alignment.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <sstream>

namespace popup {
namespace {

/// Nearest sample within a short radius, on a uniform grid: enough to score mirror planes.
class NearGrid {
public:
    NearGrid(const std::vector<Vec3>& points, double cell) : points_(points), cell_(cell)
    {
        for (const Vec3& p : points)
            box_.extend(p);
        for (int a = 0; a < 3; ++a)
            dims_[a] = std::max(1, int(std::ceil(box_.sizes()[a] / cell_)) + 1);
        cells_.assign(size_t(dims_[0]) * dims_[1] * dims_[2], {});
        for (size_t i = 0; i < points.size(); ++i) {
            const auto c = cell_of(points[i]);
            cells_[index(c[0], c[1], c[2])].push_back(int(i));
        }
    }
    /// Distance to the nearest sample, or `cell` when none is that close.
    double distance(const Vec3& q) const
    {
        const auto c = cell_of(q);
        double best = cell_ * cell_;
        for (int i = c[0] - 1; i <= c[0] + 1; ++i)
            for (int j = c[1] - 1; j <= c[1] + 1; ++j)
                for (int k = c[2] - 1; k <= c[2] + 1; ++k) {
                    if (i < 0 || j < 0 || k < 0 || i >= dims_[0] || j >= dims_[1] || k >= dims_[2])
                        continue;
                    for (int s : cells_[index(i, j, k)])
                        best = std::min(best, (points_[s] - q).squaredNorm());
                }
        return std::sqrt(best);
    }

private:
    std::array<int, 3> cell_of(const Vec3& p) const
    {
        std::array<int, 3> c{};
        for (int a = 0; a < 3; ++a)
            c[a] = int(std::floor((p[a] - box_.min()[a]) / cell_));
        return c;
    }
    size_t index(int i, int j, int k) const { return (size_t(i) * dims_[1] + j) * dims_[2] + k; }

    const std::vector<Vec3>& points_;
    double cell_;
    Eigen::AlignedBox3d box_;
    std::array<int, 3> dims_{};
    std::vector<std::vector<int>> cells_;
};

/// Third central moment of the samples along `axis`: its sign says which end has the long tail.
double skew(const std::vector<Vec3>& points, const Vec3& centre, const Vec3& axis)
{
    double m2 = 0, m3 = 0;
    for (const Vec3& p : points) {
        const double t = (p - centre).dot(axis);
        m2 += t * t;
        m3 += t * t * t;
    }
    m2 /= double(points.size());
    m3 /= double(points.size());
    return m2 > 0 ? m3 / std::pow(m2, 1.5) : 0.0;
}

/// A sign that does not depend on the model's pose when the skew decides, else a fixed rule.
Vec3 orient_by_skew(const Vec3& axis, const std::vector<Vec3>& points, const Vec3& centre)
{
    const double s = skew(points, centre, axis);
    if (std::abs(s) > 1e-3)
        return s > 0 ? axis : Vec3(-axis);
    for (int a = 0; a < 3; ++a)
        if (std::abs(axis[a]) > 1e-9)
            return axis[a] > 0 ? axis : Vec3(-axis);
    return axis;
}

/// The sign of the up axis a model stands on: the end with more flat area facing out of it at
/// its extreme (a house's floor, not its ridge); the skew decides a tie (a box).
Vec3 standing_way(const ModelMesh& model, const Vec3& axis, const std::vector<Vec3>& points,
                  const Vec3& centre)
{
    double lo = 1e300, hi = -1e300;
    for (const Vec3& v : model.vertices) {
        lo = std::min(lo, v.dot(axis));
        hi = std::max(hi, v.dot(axis));
    }
    const double tolerance = 1e-3 * (hi - lo);
    double low_area = 0, high_area = 0;
    for (const auto& t : model.triangles) {
        const Vec3 c = (model.vertices[t[1]] - model.vertices[t[0]])
                           .cross(model.vertices[t[2]] - model.vertices[t[0]]);
        const double area = 0.5 * c.norm();
        if (!(area > 0))
            continue;
        const double along = c.dot(axis) / c.norm();
        double far = -1e300, near = 1e300;
        for (int k = 0; k < 3; ++k) {
            far = std::max(far, model.vertices[t[k]].dot(axis));
            near = std::min(near, model.vertices[t[k]].dot(axis));
        }
        if (along < -0.99 && near < lo + tolerance)
            low_area += area;
        if (along > 0.99 && far > hi - tolerance)
            high_area += area;
    }
    const double total = low_area + high_area;
    if (total > 0 && std::abs(low_area - high_area) > 1e-6 * total)
        return low_area > high_area ? axis : Vec3(-axis);
    return orient_by_skew(axis, points, centre);
}

bool usable_direction(const Vec3& v)
{
    return v.allFinite() && v.norm() > 1e-12;
}

} // namespace

Mat3 normal_principal_axes(const ModelMesh& model, Vec3* eigenvalues)
{
    Mat3 covariance = Mat3::Zero();
    for (const auto& t : model.triangles) {
        const Vec3 c = (model.vertices[t[1]] - model.vertices[t[0]])
                           .cross(model.vertices[t[2]] - model.vertices[t[0]]);
        const double twice_area = c.norm();
        if (twice_area > 0)
            covariance += (0.5 / twice_area) * c * c.transpose(); // A n nᵀ = c cᵀ / (2|c|)
    }
    Eigen::SelfAdjointEigenSolver<Mat3> solver(covariance);
    Mat3 axes;
    for (int k = 0; k < 3; ++k)
        axes.col(k) = solver.eigenvectors().col(2 - k); // largest first
    if (eigenvalues)
        *eigenvalues = solver.eigenvalues().reverse();
    return axes;
}

Result<Alignment> align_model(const ModelMesh& model, const SurfaceSamples& samples,
                              const std::optional<Vec3>& up_option,
                              const std::optional<Vec3>& facing_option, const CardRoom& room)
{
    Result<Alignment> r;
    Alignment& a = r.value;
    if (up_option && !usable_direction(*up_option))
        r.fail(DiagnosticCode::bad_option,
               "up: must be a finite, non-zero 3-vector (the model direction that becomes the "
               "card's z)",
               about_parameter("up"));
    if (facing_option && !usable_direction(*facing_option))
        r.fail(DiagnosticCode::bad_option,
               "facing: must be a finite, non-zero 3-vector (the model direction that faces the "
               "viewer)",
               about_parameter("facing"));
    if (!r.ok)
        return r;
    if (samples.points.empty()) {
        r.fail(DiagnosticCode::degenerate_model,
               model.source + ": the model has no surface area to align");
        return r;
    }
    const std::vector<Vec3>& pts = samples.points;
    Vec3 centre = Vec3::Zero();
    for (const Vec3& p : pts)
        centre += p;
    centre /= double(pts.size());

    const Mat3 axes = normal_principal_axes(model);
    Vec3 up =
        up_option ? Vec3(up_option->normalized()) : standing_way(model, axes.col(0), pts, centre);
    if (facing_option) {
        const Vec3 f = *facing_option - facing_option->dot(up) * up;
        if (f.norm() < 1e-6 * facing_option->norm()) {
            r.fail(DiagnosticCode::bad_option,
                   "facing: must not be parallel to up (it gives the card's x, across the fold)",
                   about_parameter("facing"));
            return r;
        }
    }
    // A reference direction across `up` that turns with the model: the NPCA axis least
    // parallel to it.
    Vec3 e1 = axes.col(1) - axes.col(1).dot(up) * up;
    if (e1.norm() < 0.5)
        e1 = axes.col(2) - axes.col(2).dot(up) * up;
    e1.normalize();
    const Vec3 e2 = up.cross(e1);

    // Mirror planes containing `up` through the centroid: score each normal by the mean
    // distance of the mirrored samples to the model, coarse then fine.
    const double diagonal = std::max(model.diagonal(), 1e-300);
    const double cell = std::max(2.0 * samples.spacing, 1e-3 * diagonal);
    NearGrid grid(pts, cell);
    // The coarse scan mirrors 500 samples, the fine one 1500.
    const size_t fine_stride = std::max<size_t>(1, pts.size() / 1500);
    const size_t coarse_stride = std::max<size_t>(1, pts.size() / 500);
    auto score = [&](double theta, size_t stride) {
        const Vec3 n = std::cos(theta) * e1 + std::sin(theta) * e2;
        double sum = 0;
        size_t count = 0;
        for (size_t i = 0; i < pts.size(); i += stride, ++count) {
            const Vec3 q = pts[i] - 2.0 * (pts[i] - centre).dot(n) * n;
            sum += grid.distance(q);
        }
        return sum / double(count);
    };
    // Coarse scan; among planes as good as the best (a box has two), the one across the
    // model's shortest horizontal extent, so the fold runs along its length (the card is wider
    // than deep).
    std::vector<double> scores(180);
    for (int k = 0; k < 180; ++k)
        scores[k] = score(k * M_PI / 180, coarse_stride);
    const double lowest = *std::min_element(scores.begin(), scores.end());
    auto extent_along = [&](double theta) {
        const Vec3 n = std::cos(theta) * e1 + std::sin(theta) * e2;
        double lo = 1e300, hi = -1e300;
        for (const Vec3& v : model.vertices) {
            lo = std::min(lo, v.dot(n));
            hi = std::max(hi, v.dot(n));
        }
        return hi - lo;
    };
    double best_theta = 0, best = 1e300, best_extent = 1e300;
    for (int k = 0; k < 180; ++k) {
        if (scores[k] > lowest + 0.1 * samples.spacing + 1e-3 * lowest)
            continue;
        const double t = k * M_PI / 180, extent = extent_along(t);
        if (extent < best_extent * (1 - 1e-6)) {
            best_extent = extent;
            best_theta = t;
            best = scores[k];
        }
    }
    const double coarse = best_theta;
    best = score(coarse, fine_stride);
    for (int k = -10; k <= 10; ++k) {
        const double t = coarse + k * M_PI / 1800, s = score(t, fine_stride);
        if (s < best - 1e-12) {
            best = s;
            best_theta = t;
        }
    }
    // A mirror plane of a made object is usually across one of its NPCA axes: snap to it when
    // it scores as well (the scan's noise would tilt the card by a tenth of a degree).
    for (double axis_theta : {0.0, M_PI / 2}) {
        const double d = std::remainder(best_theta - axis_theta, M_PI);
        if (std::abs(d) < 2 * M_PI / 180 && score(axis_theta, fine_stride) <= best * 1.05 + 1e-12) {
            best = std::min(best, score(axis_theta, fine_stride));
            best_theta = axis_theta;
        }
    }
    const Vec3 mirror_normal = std::cos(best_theta) * e1 + std::sin(best_theta) * e2;
    a.symmetry_error = best / diagonal;

    Vec3 x, y;
    if (facing_option) {
        x = (*facing_option - facing_option->dot(up) * up).normalized();
        y = up.cross(x);
    } else {
        // The fold runs in the mirror plane; its sign (which end is the card's y = 0) is the
        // model's own, by skew, so a turned copy lands the same way.
        y = orient_by_skew(up.cross(mirror_normal), pts, centre);
        x = y.cross(up);
    }
    a.up = up;
    a.facing = x;

    Mat3 rotation;
    rotation.row(0) = x.transpose();
    rotation.row(1) = y.transpose();
    rotation.row(2) = up.transpose();
    Eigen::AlignedBox3d box;
    for (const Vec3& v : model.vertices)
        box.extend(rotation * (v - centre));
    // The fold at the middle of the model's extent across it: on a mirror-symmetric model its
    // mirror plane, exactly (the samples' centroid is only near it).
    const double middle = box.center().x();
    centre += middle * x;
    box.translate(Vec3(-middle, 0, 0));
    const double half_x = std::max(-box.min().x(), box.max().x());
    const double length = box.sizes().y(), height = box.sizes().z();
    const double usable_w = room.width * (1 - 2 * room.margin);
    const double usable_d = room.depth * (1 - 2 * room.margin);
    // Closed, a box of height c and half depth g reaches c + g from the fold along the page
    // (docs/MATH.md, Fitting): the model's height plus its half depth must fit on one page.
    // Closed, a box's end panels stand out of its ends by its half depth: the length plus
    // both must fit along the fold.
    a.scale = std::min(usable_w / std::max(length + 2 * half_x, 1e-300),
                       usable_d / std::max(height + half_x, 1e-300));
    const Vec3 shift(0, room.width / 2 - a.scale * box.center().y(), -a.scale * box.min().z());
    a.model_to_card.setIdentity();
    a.model_to_card.topLeftCorner<3, 3>() = a.scale * rotation;
    a.model_to_card.topRightCorner<3, 1>() = shift - a.scale * rotation * centre;
    a.card_box = Eigen::AlignedBox3d(a.scale * box.min() + shift, a.scale * box.max() + shift);
    return r;
}

} // namespace popup
