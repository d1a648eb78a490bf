// A small orthographic z-buffer rasteriser: the preview of `popup fit` (the model beside the
// pop-up), fast enough for a scanned model's tens of thousands of triangles.
#include "popup/sheets/render_view.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Geometry>

namespace popup {

namespace {

constexpr int kBandRows = 32; ///< output rows drawn at a time

/// A point on the screen: x right and y down in (supersampled) pixels, depth towards the eye in
/// mm.
struct ScreenPoint {
    double x, y, depth;
};

using Pixel = std::array<std::uint8_t, 4>;
using ScreenLoops = std::vector<std::vector<ScreenPoint>>;

Pixel rgba(const Vec3& colour, std::uint8_t alpha)
{
    auto channel = [](double v) {
        return std::uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
    };
    return {channel(colour.x()), channel(colour.y()), channel(colour.z()), alpha};
}

/// The camera's projection and shading.
struct Projection {
    explicit Projection(const ViewCamera& camera)
        : camera(camera), scale(camera.supersample), width(camera.width * scale),
          height(camera.height * scale), mm_per_pixel(camera.mm_per_pixel / scale)
    {
        eye = camera.towards_eye.normalized();
        up = (camera.up - camera.up.dot(eye) * eye).normalized();
        right = up.cross(eye);
        light = camera.light.normalized();
    }

    ScreenPoint project(const Vec3& p) const
    {
        const Vec3 d = p - camera.centre;
        return {0.5 * width + d.dot(right) / mm_per_pixel, 0.5 * height - d.dot(up) / mm_per_pixel,
                d.dot(eye)};
    }

    /// colour × (ambient + (1 − ambient) |n · light|), n the unit normal (two-sided).
    Pixel shaded(const Vec3& colour, const Vec3& normal) const
    {
        const double n = normal.norm();
        const double lit = n > 0 ? std::abs(normal.dot(light)) / n : 0.5;
        return rgba(colour * (camera.ambient + (1.0 - camera.ambient) * lit), 255);
    }

    const ViewCamera& camera;
    int scale, width, height; ///< supersampled size
    double mm_per_pixel;      ///< of a supersampled pixel
    Vec3 eye, up, right, light;
};

/// A surface to fill: its loops on the screen, its colour and the rows it spans.
struct ScreenSurface {
    ScreenLoops loops;
    Pixel colour;
    double top = INFINITY, bottom = -INFINITY;
    bool outlined = false;
};

/// `value` (may be huge or not finite: a point far off the screen) as an int in [lo, hi].
int clamped(double value, int lo, int hi)
{
    if (!(value > lo))
        return lo;
    return value < hi ? int(value) : hi;
}

/// The part of segment a-b inside x in [x0, x1], y in [y0, y1] (Liang-Barsky); false when none.
bool clip(ScreenPoint& a, ScreenPoint& b, double x0, double x1, double y0, double y1)
{
    double t0 = 0.0, t1 = 1.0;
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {a.x - x0, x1 - a.x, a.y - y0, y1 - a.y};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0) {
            if (q[i] < 0.0)
                return false;
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0.0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
    }
    if (!(t0 <= t1))
        return false;
    const ScreenPoint from = a;
    auto at = [&](double t) {
        return ScreenPoint{from.x + t * dx, from.y + t * dy,
                           from.depth + t * (b.depth - from.depth)};
    };
    const ScreenPoint end = at(t1);
    a = at(t0);
    b = end;
    return true;
}

/// A band of the supersampled frame, rows [first, first + rows): drawn band after band so the
/// buffers stay small (touching fresh memory is what costs most in a large frame).
class Band {
public:
    Band(const Projection& view, int rows)
        : view_(view), width_(view.width), capacity_(rows), depth_(size_t(width_) * rows),
          rgba_(depth_.size())
    {
    }

    void start(int first)
    {
        first_ = first;
        rows_ = std::min(capacity_, view_.height - first);
        std::fill(depth_.begin(), depth_.end(), -std::numeric_limits<float>::infinity());
        std::fill(rgba_.begin(), rgba_.end(), rgba(view_.camera.background, 0));
    }
    bool overlaps(double top, double bottom) const
    {
        return bottom >= first_ - 1.0 && top <= first_ + rows_ + 1.0;
    }

    /// Even-odd fill of the loops on the plane through them.
    void fill(const ScreenLoops& loops, const Pixel& colour)
    {
        Vec3 normal = Vec3::Zero(), anchor = Vec3::Zero();
        double lo = INFINITY, hi = -INFINITY;
        int count = 0;
        for (const auto& loop : loops)
            for (size_t i = 0; i < loop.size(); ++i) {
                const ScreenPoint &a = loop[i], &b = loop[(i + 1) % loop.size()];
                normal += Vec3((a.y - b.y) * (a.depth + b.depth), (a.depth - b.depth) * (a.x + b.x),
                               (a.x - b.x) * (a.y + b.y));
                anchor += Vec3(a.x, a.y, a.depth);
                lo = std::min(lo, a.y);
                hi = std::max(hi, a.y);
                ++count;
            }
        // Seen edge on (or degenerate): nothing to fill, the outline still shows it.
        if (count < 3 || !(std::abs(normal.z()) > 1e-9 * normal.norm()))
            return;
        anchor /= count;
        const double dx = -normal.x() / normal.z(), dy = -normal.y() / normal.z();
        const int first = clamped(std::ceil(lo - 0.5), first_, first_ + rows_);
        const int last = clamped(std::floor(hi - 0.5), first_ - 1, first_ + rows_ - 1);
        std::vector<double>& crossings = crossings_;
        for (int row = first; row <= last; ++row) {
            const double y = row + 0.5;
            crossings.clear();
            for (const auto& loop : loops)
                for (size_t i = 0; i < loop.size(); ++i) {
                    const ScreenPoint &a = loop[i], &b = loop[(i + 1) % loop.size()];
                    if ((a.y <= y) != (b.y <= y))
                        crossings.push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
                }
            std::sort(crossings.begin(), crossings.end());
            for (size_t k = 0; k + 1 < crossings.size(); k += 2) {
                const int from = clamped(std::ceil(crossings[k] - 0.5), 0, width_);
                const int to = clamped(std::ceil(crossings[k + 1] - 0.5), 0, width_);
                for (int column = from; column < to; ++column) {
                    const double depth =
                        anchor.z() + dx * (column + 0.5 - anchor.x()) + dy * (y - anchor.y());
                    put(column, row, depth, colour);
                }
            }
        }
    }

    /// A line `edge_px` wide over the surfaces it lies on, hidden behind nearer ones.
    void line(ScreenPoint a, ScreenPoint b)
    {
        const double half = 0.5 * view_.camera.edge_px * view_.scale;
        // Only the part over the band: a point far off the screen would take endless steps.
        if (!clip(a, b, -half, width_ + half, first_ - half - 1.0, first_ + rows_ + half + 1.0))
            return;
        const double length = std::hypot(b.x - a.x, b.y - a.y);
        const int steps = std::max(1, int(std::ceil(2.0 * length)));
        // A surface seen at a slant changes depth by up to a few mm_per_pixel across a pixel.
        const double tolerance = 3.0 * view_.mm_per_pixel * std::max(1.0, 2.0 * half);
        const Pixel edge = rgba(view_.camera.edge_colour, 255);
        for (int s = 0; s <= steps; ++s) {
            const double t = double(s) / steps;
            const double x = a.x + t * (b.x - a.x), y = a.y + t * (b.y - a.y);
            const double depth = a.depth + t * (b.depth - a.depth);
            const int c0 = std::max(0, int(std::ceil(x - half - 0.5)));
            const int c1 = std::min(width_ - 1, int(std::floor(x + half - 0.5)));
            const int r0 = std::max(first_, int(std::ceil(y - half - 0.5)));
            const int r1 = std::min(first_ + rows_ - 1, int(std::floor(y + half - 0.5)));
            for (int r = r0; r <= r1; ++r)
                for (int c = c0; c <= c1; ++c) {
                    const size_t i = size_t(r - first_) * width_ + c;
                    if (depth + tolerance >= depth_[i])
                        rgba_[i] = edge;
                }
        }
    }

    /// The band's rows averaged over supersample x supersample blocks into `out` (alpha too:
    /// edges blend).
    void resolve(RgbaImage& out) const
    {
        const int k = view_.scale, n = k * k;
        for (int row = first_ / k; row < (first_ + rows_) / k; ++row)
            for (int column = 0; column < out.width; ++column) {
                int sum[4] = {0, 0, 0, 0};
                for (int dr = 0; dr < k; ++dr)
                    for (int dc = 0; dc < k; ++dc) {
                        const Pixel& p =
                            rgba_[size_t(row * k + dr - first_) * width_ + column * k + dc];
                        for (int c = 0; c < 4; ++c)
                            sum[c] += p[c];
                    }
                std::uint8_t* to = out.at(column, row);
                for (int c = 0; c < 4; ++c)
                    to[c] = std::uint8_t((sum[c] + n / 2) / n);
            }
    }

private:
    void put(int column, int row, double depth, const Pixel& colour)
    {
        const size_t i = size_t(row - first_) * width_ + column;
        if (float(depth) > depth_[i]) {
            depth_[i] = float(depth);
            rgba_[i] = colour;
        }
    }

    const Projection& view_;
    int width_, capacity_, first_ = 0, rows_ = 0;
    std::vector<float> depth_;
    std::vector<Pixel> rgba_;
    std::vector<double> crossings_;
};

/// Every triangle and polygon on the screen, in drawing order: the meshes, then the polygons.
std::vector<ScreenSurface> project_scene(const Projection& view,
                                         const std::vector<ViewMesh>& meshes,
                                         const std::vector<ViewPolygon>& polygons)
{
    std::vector<ScreenSurface> out;
    auto span = [](ScreenSurface& s) {
        for (const auto& loop : s.loops)
            for (const ScreenPoint& p : loop) {
                s.top = std::min(s.top, p.y);
                s.bottom = std::max(s.bottom, p.y);
            }
    };
    for (const ViewMesh& mesh : meshes) {
        std::vector<ScreenPoint> screen;
        screen.reserve(mesh.vertices.size());
        for (const Vec3& v : mesh.vertices)
            screen.push_back(view.project(v));
        for (const auto& t : mesh.triangles) {
            const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
            ScreenSurface& s = out.emplace_back();
            s.loops = {{screen[t[0]], screen[t[1]], screen[t[2]]}};
            s.colour = view.shaded(mesh.colour, (b - a).cross(c - a));
            span(s);
        }
    }
    for (const ViewPolygon& polygon : polygons) {
        Vec3 normal = Vec3::Zero(); // Newell's: any planar polygon
        ScreenSurface& s = out.emplace_back();
        for (const auto& loop : polygon.loops) {
            auto& screen = s.loops.emplace_back();
            for (size_t i = 0; i < loop.size(); ++i) {
                normal += loop[i].cross(loop[(i + 1) % loop.size()]);
                screen.push_back(view.project(loop[i]));
            }
        }
        s.colour = view.shaded(polygon.colour, normal);
        s.outlined = polygon.outlined && view.camera.edge_px > 0;
        span(s);
    }
    return out;
}

Diagnostics check_camera(const ViewCamera& c)
{
    Diagnostics out;
    auto bad = [&](const std::string& name, const std::string& what) {
        out.push_back(Diagnostic::error(DiagnosticCode::bad_option,
                                        "render view: " + name + " " + what,
                                        about_parameter(name)));
    };
    const Vec3 eye = c.towards_eye.allFinite() ? c.towards_eye.normalized() : Vec3::Zero();
    if (!c.towards_eye.allFinite() || !(c.towards_eye.norm() > 0))
        bad("towards_eye", "must be finite and non-zero");
    if (!c.up.allFinite() || !((c.up - c.up.dot(eye) * eye).norm() > 1e-9 * c.up.norm()))
        bad("up", "must be finite, non-zero and not along towards_eye");
    if (!c.centre.allFinite())
        bad("centre", "must be finite");
    if (!(c.mm_per_pixel > 0) || !std::isfinite(c.mm_per_pixel))
        bad("mm_per_pixel", "= " + std::to_string(c.mm_per_pixel) + ", must be finite and > 0");
    if (c.width < 1 || c.width > 8192 || c.height < 1 || c.height > 8192)
        bad("size", "= " + std::to_string(c.width) + " x " + std::to_string(c.height) +
                        " pixels, each must be in 1..8192");
    if (c.supersample < 1 || c.supersample > 4)
        bad("supersample", "= " + std::to_string(c.supersample) + ", must be in 1..4");
    if (!c.light.allFinite() || !(c.light.norm() > 0))
        bad("light", "must be finite and non-zero");
    if (!(c.ambient >= 0.0 && c.ambient <= 1.0))
        bad("ambient", "= " + std::to_string(c.ambient) + ", must be in [0, 1]");
    if (!(c.edge_px >= 0.0 && c.edge_px <= 16.0))
        bad("edge_px", "= " + std::to_string(c.edge_px) + ", must be in [0, 16]");
    if (!c.background.allFinite() || !c.edge_colour.allFinite())
        bad("background", "and edge_colour must be finite");
    return out;
}

Diagnostics check_scene(const std::vector<ViewMesh>& meshes,
                        const std::vector<ViewPolygon>& polygons)
{
    Diagnostics out;
    auto bad = [&](const std::string& name, const std::string& what) {
        out.push_back(Diagnostic::error(DiagnosticCode::bad_option,
                                        "render view: " + name + " " + what,
                                        about_parameter(name)));
    };
    for (size_t m = 0; m < meshes.size(); ++m) {
        const std::string name = "meshes[" + std::to_string(m) + "]";
        const int n = int(meshes[m].vertices.size());
        if (!std::all_of(meshes[m].vertices.begin(), meshes[m].vertices.end(),
                         [](const Vec3& v) { return v.allFinite(); }))
            bad(name, "has a non-finite vertex, vertices must be finite");
        for (const auto& t : meshes[m].triangles)
            if (std::any_of(t.begin(), t.end(), [&](int k) { return k < 0 || k >= n; })) {
                bad(name, "has a triangle index outside 0.." + std::to_string(n - 1));
                break;
            }
    }
    for (size_t p = 0; p < polygons.size(); ++p)
        for (const auto& loop : polygons[p].loops)
            if (!std::all_of(loop.begin(), loop.end(), [](const Vec3& v) { return v.allFinite(); }))
                bad("polygons[" + std::to_string(p) + "]",
                    "has a non-finite point, points must be finite");
    return out;
}

} // namespace

Result<RgbaImage> render_view(const std::vector<ViewMesh>& meshes,
                              const std::vector<ViewPolygon>& polygons, const ViewCamera& camera)
{
    Result<RgbaImage> r;
    r.diagnostics = check_camera(camera);
    const Diagnostics problems = check_scene(meshes, polygons);
    r.diagnostics.insert(r.diagnostics.end(), problems.begin(), problems.end());
    if (has_errors(r.diagnostics)) {
        r.ok = false;
        return r;
    }
    const Projection view(camera);
    const std::vector<ScreenSurface> scene = project_scene(view, meshes, polygons);
    r.value.width = camera.width;
    r.value.height = camera.height;
    r.value.pixels.resize(size_t(4) * camera.width * camera.height);
    Band band(view, kBandRows * view.scale);
    for (int first = 0; first < view.height; first += kBandRows * view.scale) {
        band.start(first);
        for (const ScreenSurface& s : scene)
            if (band.overlaps(s.top, s.bottom))
                band.fill(s.loops, s.colour);
        // Outlines last, so a later surface does not cover an earlier one's edge lying on it.
        for (const ScreenSurface& s : scene)
            if (s.outlined)
                for (const auto& loop : s.loops)
                    for (size_t i = 0; i < loop.size(); ++i)
                        band.line(loop[i], loop[(i + 1) % loop.size()]);
        band.resolve(r.value);
    }
    return r;
}

} // namespace popup
