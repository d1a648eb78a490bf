#include "popup/fitting/alignment.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <map>
#include <sstream>

#include "model_walls.hpp"

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

/// Flat area facing out of the model at each end of `axis`, of faces lying wholly in the end
/// plane (within a thousandth of the extent):
/// [0] at the low end facing down, [1] at the high end facing up.
std::array<double, 2> end_areas(const ModelMesh& model, const Vec3& axis)
{
    double lo = 1e300, hi = -1e300;
    for (const Vec3& v : model.vertices) {
        lo = std::min(lo, v.dot(axis));
        hi = std::max(hi, v.dot(axis));
    }
    const double tolerance = 1e-3 * (hi - lo);
    std::array<double, 2> area{0, 0};
    for (const auto& t : model.triangles) {
        const Vec3 c = (model.vertices[t[1]] - model.vertices[t[0]])
                           .cross(model.vertices[t[2]] - model.vertices[t[0]]);
        const double twice = c.norm();
        if (!(twice > 0))
            continue;
        const double along = c.dot(axis) / twice;
        double far = -1e300, near = 1e300;
        for (int k = 0; k < 3; ++k) {
            far = std::max(far, model.vertices[t[k]].dot(axis));
            near = std::min(near, model.vertices[t[k]].dot(axis));
        }
        // The whole face in the end plane: a facet of a round side only touches it.
        if (along < -0.99 && far < lo + tolerance)
            area[0] += 0.5 * twice;
        if (along > 0.99 && near > hi - tolerance)
            area[1] += 0.5 * twice;
    }
    return area;
}

/// `axis` turned onto the area-weighted mean normal of the faces within 3° of it (either
/// sense): an NPCA axis a little off a large flat face (a terrain slab under a house whose roof
/// is not quite symmetric) lies in it again, so that face is the model's flat end.
Vec3 snapped_to_faces(const ModelMesh& model, const Vec3& axis)
{
    const double within = std::cos(3.0 * M_PI / 180.0);
    Vec3 sum = Vec3::Zero();
    for (const auto& t : model.triangles) {
        const Vec3 c = (model.vertices[t[1]] - model.vertices[t[0]])
                           .cross(model.vertices[t[2]] - model.vertices[t[0]]);
        const double twice = c.norm();
        if (!(twice > 0))
            continue;
        const double along = c.dot(axis) / twice;
        if (std::abs(along) >= within)
            sum += along > 0 ? c : Vec3(-c); // c's length is twice the face's area
    }
    return sum.norm() > 0 ? Vec3(sum.normalized()) : axis;
}

constexpr double kWideStance = 0.04; ///< feet, not a corner (widest_stance's measure)

/// Where a model would stand along `up`: the bounding rectangle (across `up`) of the vertices in
/// the lowest 3 % of its height (its feet) and that of all its vertices (its footprint).
struct Stance {
    double feet = 0.0, footprint = 0.0;
};

Stance stance(const ModelMesh& model, const Vec3& up)
{
    const Vec3 e1 = up.unitOrthogonal(), e2 = up.cross(e1);
    double lo = 1e300, hi = -1e300;
    for (const Vec3& v : model.vertices) {
        lo = std::min(lo, v.dot(up));
        hi = std::max(hi, v.dot(up));
    }
    Eigen::AlignedBox2d all, feet;
    for (const Vec3& v : model.vertices) {
        const Vec2 q(v.dot(e1), v.dot(e2));
        all.extend(q);
        if (v.dot(up) <= lo + 0.03 * (hi - lo))
            feet.extend(q);
    }
    return {feet.volume(), all.volume()};
}

/// A model with no flat bottom (an animal, a figure, a scan): the signed NPCA axis it stands on
/// most widely (its feet's rectangle over its footprint, times the square root of that footprint
/// over the largest of the three axes'), the first's among equals, so that
/// a dog stands on its legs rather than on its flank (turned onto the file's own axis within 15° of
/// it); the first NPCA axis when no stance reaches kWideStance.
Vec3 widest_stance(const ModelMesh& model, const Mat3& axes)
{
    // Feet over the footprint, weighed by the square root of how large that footprint is among
    // the three axes': a dog's paws spread wider than its flank lies, and a thin plate on its
    // edge, whose footprint is a line, stands narrowly however long the line.
    std::array<Stance, 6> stances;
    double largest = 0;
    for (int k = 0; k < 6; ++k) {
        stances[size_t(k)] = stance(model, (k % 2 ? -1.0 : 1.0) * axes.col(k / 2));
        largest = std::max(largest, stances[size_t(k)].footprint);
    }
    Vec3 best = axes.col(0);
    double widest = -1;
    for (int k = 0; k < 6; ++k) {
        const Stance& st = stances[size_t(k)];
        const double w = st.footprint > 0 && largest > 0
                             ? st.feet / st.footprint * std::sqrt(st.footprint / largest)
                             : 0.0;
        if (w > widest * 1.05) {
            widest = w;
            best = (k % 2 ? -1.0 : 1.0) * axes.col(k / 2);
        }
    }
    // Nothing stands widely (a tree on its trunk, a pole): the thesis's up, the first NPCA axis.
    if (widest < kWideStance)
        return axes.col(0);
    // An animal's NPCA axes lean with its tail and head; files model it upright along one of
    // their own axes, so an axis of the file within 15° is its up.
    for (int a = 0; a < 3; ++a)
        if (std::abs(best[a]) >= std::cos(15.0 * M_PI / 180.0))
            return best[a] > 0 ? Vec3(Vec3::Unit(a)) : Vec3(-Vec3::Unit(a));
    return best;
}

/// The up a model stands on (docs/MATH.md, "Which way is up"): the signed NPCA axis whose
/// bounding-box bottom carries the most flat, downward-facing area (a house's floor, not its
/// roof; an upright cylinder's cap, not a facet of its side). Axes whose bottoms are within
/// 10 % of the largest are as good (a truck's floor and its flat side): the larger NPCA
/// eigenvalue decides among them, the thesis's up (each axis snapped onto the flat faces within
/// 3° of it first). A model with no flat bottom worth the name (under 1 % of its area: a blob,
/// an animal) stands on its widest stance (widest_stance). The sign: the end with more flat
/// area, the skew deciding a tie.
Vec3 standing_up(const ModelMesh& model, const Mat3& npca, const std::vector<Vec3>& points,
                 const Vec3& centre)
{
    Mat3 axes;
    for (int k = 0; k < 3; ++k)
        axes.col(k) = snapped_to_faces(model, npca.col(k));
    double total = 0;
    for (const auto& t : model.triangles)
        total += 0.5 * (model.vertices[t[1]] - model.vertices[t[0]])
                           .cross(model.vertices[t[2]] - model.vertices[t[0]])
                           .norm();
    std::array<std::array<double, 2>, 3> areas{};
    double largest = 0;
    for (int k = 0; k < 3; ++k) {
        areas[k] = end_areas(model, axes.col(k));
        largest = std::max({largest, areas[k][0], areas[k][1]});
    }
    if (largest < 0.01 * total)
        return widest_stance(model, axes);
    // A flat bottom worth the name (returned above otherwise): the first axis as good as the best.
    int best_axis = -1;
    for (int k = 0; k < 3 && best_axis < 0; ++k)
        if (std::max(areas[k][0], areas[k][1]) >= 0.9 * largest)
            best_axis = k;
    const int k = best_axis < 0 ? 0 : best_axis;
    const Vec3 axis = axes.col(k);
    const double low = areas[k][0], high = areas[k][1], sum = low + high;
    if (sum > 0 && std::abs(low - high) > 1e-6 * sum)
        return low > high ? axis : Vec3(-axis);
    return orient_by_skew(axis, points, centre);
}

/// The alignment for the card axes (x toward the viewer, y along the fold, up) with the central
/// fold on the plane x · p = fold_at (model units), or at the middle of the model's extent
/// across it when `fold_at` is empty.
Alignment placed(const ModelMesh& model, const Vec3& x, const Vec3& y, const Vec3& up,
                 const std::optional<double>& fold_at, const CardRoom& room)
{
    Alignment a;
    a.up = up;
    a.facing = x;
    Mat3 rotation;
    rotation.row(0) = x.transpose();
    rotation.row(1) = y.transpose();
    rotation.row(2) = up.transpose();
    Eigen::AlignedBox3d box;
    for (const Vec3& v : model.vertices)
        box.extend(rotation * v);
    // The fold at the middle of the model's extent across it: on a mirror-symmetric model its
    // mirror plane, exactly.
    const double fold = fold_at ? *fold_at : box.center().x();
    Vec3 centre = rotation.transpose() * Vec3(fold, 0, 0);
    box.translate(Vec3(-fold, 0, 0));
    const double half_x = std::max(-box.min().x(), box.max().x());
    const double length = box.sizes().y(), height = box.sizes().z();
    const double usable_w = room.card.width * (1 - 2 * room.margin);
    const double usable_d = room.card.depth * (1 - 2 * room.margin);
    // Closed, a box of height c and half depth g reaches c + g from the fold along the page
    // (docs/MATH.md, Fitting): the model's height plus its half depth must fit on one page.
    // Closed, a box's end panels stand out of its ends by its half depth: the length plus
    // both must fit along the fold.
    a.scale = std::min(usable_w / std::max(length + 2 * half_x, 1e-300),
                       usable_d / std::max(height + half_x, 1e-300));
    const Vec3 shift(0, room.card.width / 2 - a.scale * box.center().y(), -a.scale * box.min().z());
    a.model_to_card.setIdentity();
    a.model_to_card.topLeftCorner<3, 3>() = a.scale * rotation;
    a.model_to_card.topRightCorner<3, 1>() = shift - a.scale * rotation * centre;
    a.card_box = Eigen::AlignedBox3d(a.scale * box.min() + shift, a.scale * box.max() + shift);
    return a;
}

bool usable_direction(const Vec3& v)
{
    return v.allFinite() && v.norm() > 1e-12;
}

/// A mirror symmetric model mirrors its samples onto themselves: the mean distance is then the
/// nearest-sample distance, under one sample spacing. Above it the plane is not a mirror plane.
bool mirror_plane(double mean_mirror_distance, double spacing)
{
    return mean_mirror_distance <= spacing;
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

namespace {

/// Mirror planes containing `up` (across e1 and e2) scored by the mean distance of the mirrored
/// samples to the model.
class MirrorScores {
public:
    MirrorScores(const ModelMesh& model, const std::vector<Vec3>& pts, const Vec3& centre,
                 const Vec3& e1, const Vec3& e2, double cell)
        : model_(model), pts_(pts), centre_(centre), e1_(e1), e2_(e2), grid_(pts, cell)
    {
    }

    /// The plane of normal n through the middle of the model's extent along n (a mirror plane
    /// passes there), every `stride`-th sample mirrored.
    double normal(const Vec3& n, size_t stride) const
    {
        double lo = 1e300, hi = -1e300;
        for (const Vec3& v : model_.vertices) {
            lo = std::min(lo, v.dot(n));
            hi = std::max(hi, v.dot(n));
        }
        const double middle = 0.5 * (lo + hi);
        double sum = 0;
        size_t count = 0;
        for (size_t i = 0; i < pts_.size(); i += stride, ++count) {
            const Vec3 q = pts_[i] - 2.0 * (pts_[i].dot(n) - middle) * n;
            sum += grid_.distance(q);
        }
        return sum / double(count);
    }

    /// The plane through the centroid whose normal is at `theta` from e1 towards e2.
    double at(double theta, size_t stride) const
    {
        const Vec3 n = std::cos(theta) * e1_ + std::sin(theta) * e2_;
        double sum = 0;
        size_t count = 0;
        for (size_t i = 0; i < pts_.size(); i += stride, ++count) {
            const Vec3 q = pts_[i] - 2.0 * (pts_[i] - centre_).dot(n) * n;
            sum += grid_.distance(q);
        }
        return sum / double(count);
    }

    /// The model's extent along the normal at `theta`.
    double extent_along(double theta) const
    {
        const Vec3 n = std::cos(theta) * e1_ + std::sin(theta) * e2_;
        double lo = 1e300, hi = -1e300;
        for (const Vec3& v : model_.vertices) {
            lo = std::min(lo, v.dot(n));
            hi = std::max(hi, v.dot(n));
        }
        return hi - lo;
    }

private:
    const ModelMesh& model_;
    const std::vector<Vec3>& pts_;
    Vec3 centre_, e1_, e2_;
    NearGrid grid_;
};

/// The angle of the best mirror plane (its fine score in `best`): a coarse scan; among planes as
/// good as the best (a box has two), the one across the model's shortest horizontal extent, so
/// the fold runs along its length (the card is wider than deep); then a fine scan around it.
double best_mirror_angle(const MirrorScores& mirror, size_t coarse_stride, size_t fine_stride,
                         double spacing, double& best)
{
    std::vector<double> scores(180);
    auto scan = [&](int from, int to) {
        for (int k = from; k < to; ++k)
            scores[k] = mirror.at(k * M_PI / 180, coarse_stride);
    };
    // Each angle scores on its own: half of them on the other core.
    std::future<void> other = std::async(std::launch::async, scan, 90, 180);
    scan(0, 90);
    other.get();
    const double lowest = *std::min_element(scores.begin(), scores.end());
    double best_theta = 0, best_extent = 1e300;
    best = 1e300;
    for (int k = 0; k < 180; ++k) {
        if (scores[k] > lowest + 0.1 * spacing + 1e-3 * lowest)
            continue;
        const double t = k * M_PI / 180, extent = mirror.extent_along(t);
        if (extent < best_extent * (1 - 1e-6)) {
            best_extent = extent;
            best_theta = t;
            best = scores[k];
        }
    }
    const double coarse = best_theta;
    best = mirror.at(coarse, fine_stride);
    for (int k = -10; k <= 10; ++k) {
        const double t = coarse + k * M_PI / 1800, s = mirror.at(t, fine_stride);
        if (s < best - 1e-12) {
            best = s;
            best_theta = t;
        }
    }
    // A mirror plane of a made object is usually across one of its NPCA axes: snap to it when
    // it scores as well (the scan's noise would tilt the card by a tenth of a degree).
    for (double axis_theta : {0.0, M_PI / 2}) {
        const double d = std::remainder(best_theta - axis_theta, M_PI);
        if (std::abs(d) < 2 * M_PI / 180 &&
            mirror.at(axis_theta, fine_stride) <= best * 1.05 + 1e-12) {
            best = std::min(best, mirror.at(axis_theta, fine_stride));
            best_theta = axis_theta;
        }
    }
    return best_theta;
}

Vec3 centroid(const std::vector<Vec3>& points)
{
    Vec3 centre = Vec3::Zero();
    for (const Vec3& p : points)
        centre += p;
    return points.empty() ? centre : Vec3(centre / double(points.size()));
}

/// The alignments for a given up (alignment_candidates' mirror planes, axes and folds).
std::vector<Alignment> aligned_on(const ModelMesh& model, const SurfaceSamples& samples,
                                  const Mat3& axes, const Vec3& up,
                                  const std::optional<Vec3>& facing_option, const CardRoom& room)
{
    std::vector<Alignment> out;
    const std::vector<Vec3>& pts = samples.points;
    const Vec3 centre = centroid(pts);
    // A reference direction across `up` that turns with the model: the NPCA axis least
    // parallel to it.
    Vec3 e1 = axes.col(1) - axes.col(1).dot(up) * up;
    if (e1.norm() < 0.5)
        e1 = axes.col(2) - axes.col(2).dot(up) * up;
    if (e1.norm() < 0.5)
        e1 = axes.col(0) - axes.col(0).dot(up) * up;
    e1.normalize();
    const Vec3 e2 = up.cross(e1);

    // Mirror planes containing `up` through the centroid: score each normal by the mean
    // distance of the mirrored samples to the model, coarse then fine.
    const double diagonal = std::max(model.diagonal(), 1e-300);
    const double cell = std::max(2.0 * samples.spacing, 1e-3 * diagonal);
    const MirrorScores mirror(model, pts, centre, e1, e2, cell);
    // The coarse scan mirrors 500 samples, the fine one 1500.
    const size_t fine_stride = std::max<size_t>(1, pts.size() / 1500);
    const size_t coarse_stride = std::max<size_t>(1, pts.size() / 500);
    double best = 1e300;
    const double best_theta =
        best_mirror_angle(mirror, coarse_stride, fine_stride, samples.spacing, best);
    const Vec3 mirror_normal = std::cos(best_theta) * e1 + std::sin(best_theta) * e2;

    // Directions across the fold: the facing given, else the mirror plane's normal first, then
    // (a model with no mirror plane across its NPCA axes, an L) the horizontal NPCA axes.
    std::vector<Vec3> normals;
    if (facing_option) {
        normals.push_back((*facing_option - facing_option->dot(up) * up).normalized());
    } else {
        normals.push_back(mirror_normal);
        if (!mirror_plane(best, samples.spacing))
            for (const Vec3& n : {e1, e2})
                if (std::abs(n.dot(mirror_normal)) < std::cos(2 * M_PI / 180))
                    normals.push_back(n);
    }
    double total_area = 0;
    for (const auto& t : model.triangles)
        total_area += 0.5 * (model.vertices[t[1]] - model.vertices[t[0]])
                                .cross(model.vertices[t[2]] - model.vertices[t[0]])
                                .norm();
    for (size_t k = 0; k < normals.size(); ++k) {
        const Vec3& n = normals[k];
        Vec3 x, y;
        if (facing_option) {
            x = n;
            y = up.cross(x);
        } else {
            // The fold runs in the mirror plane; its sign (which end is the card's y = 0) is
            // the model's own, by skew, so a turned copy lands the same way.
            y = orient_by_skew(up.cross(n), pts, centre);
            x = y.cross(up);
        }
        const double mirrored = k == 0 && !facing_option ? best : mirror.normal(x, fine_stride);
        std::vector<std::optional<double>> folds{std::nullopt};
        // No mirror plane across x: the fold may stand on one of the model's inner walls
        // across x instead, where a box's backbone is the wall (each a twentieth of its area).
        // Or through the middle of one of its blocks, where a box centred on the fold stands.
        if (!mirror_plane(mirrored, samples.spacing)) {
            for (double at : inner_walls(model, x, 0.05 * total_area, 2))
                folds.push_back(at);
            for (double at : block_centres(model, x, y, 0.02 * total_area, 2))
                folds.push_back(at);
        }
        for (const auto& fold : folds) {
            Alignment a = placed(model, x, y, up, fold, room);
            a.symmetry_error = mirrored / diagonal;
            out.push_back(a);
        }
    }
    return out;
}

} // namespace

Result<std::vector<Alignment>> alignment_candidates(const ModelMesh& model,
                                                    const SurfaceSamples& samples,
                                                    const std::optional<Vec3>& up_option,
                                                    const std::optional<Vec3>& facing_option,
                                                    const CardRoom& room)
{
    Result<std::vector<Alignment>> r;
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
    const Mat3 axes = normal_principal_axes(model);
    const Vec3 up = up_option ? Vec3(up_option->normalized())
                              : standing_up(model, axes, samples.points, centroid(samples.points));
    if (facing_option) {
        const Vec3 f = *facing_option - facing_option->dot(up) * up;
        if (f.norm() < 1e-6 * facing_option->norm()) {
            r.fail(DiagnosticCode::bad_option,
                   "facing: must not be parallel to up (it gives the card's x, across the fold)",
                   about_parameter("facing"));
            return r;
        }
    }
    // On a plate (a terrain slab, a print bed), what stands on it is placed on the card and the
    // plate becomes the page (docs/MATH.md, "The plate under a model").
    const std::optional<SupportingPlate> plate = supporting_plate(model, up);
    if (!plate) {
        r.value = aligned_on(model, samples, axes, up, facing_option, room);
        return r;
    }
    const ModelMesh standing = above_plate(model, *plate);
    const SurfaceSamples above = samples_above(*plate, samples);
    r.value =
        aligned_on(standing, above.points.empty() ? samples : above, axes, up, facing_option, room);
    for (Alignment& a : r.value)
        a.plate = plate;
    return r;
}

Result<Alignment> align_model(const ModelMesh& model, const SurfaceSamples& samples,
                              const std::optional<Vec3>& up_option,
                              const std::optional<Vec3>& facing_option, const CardRoom& room)
{
    Result<Alignment> r;
    Result<std::vector<Alignment>> all =
        alignment_candidates(model, samples, up_option, facing_option, room);
    r.diagnostics = all.diagnostics;
    r.ok = all.ok;
    if (all.ok)
        r.value = all.value.front();
    return r;
}

} // namespace popup
