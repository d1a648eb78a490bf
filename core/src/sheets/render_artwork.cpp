#include "popup/sheets/render_artwork.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <future>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>

#include "popup/input/model_texture.hpp"

namespace popup {

namespace {

constexpr double kMaxPixelsPerMm = 40.0; // 1016 dpi: beyond what printers resolve
constexpr long long kMaxPixelsCap = 100'000'000;

std::string number(double value)
{
    std::ostringstream s;
    s << value;
    return s.str();
}

std::string whole(double count)
{
    std::ostringstream s;
    s << std::fixed << std::setprecision(0) << count;
    return s.str();
}

std::string model_name(const ModelMesh& mesh)
{
    return mesh.source.empty() ? std::string("model") : mesh.source;
}

/// What colours a pixel, settled once per model: the decoded texture, or per-vertex colours, or
/// the shaded base colour.
struct Appearance {
    std::optional<RgbaImage> texture;
    bool vertex_colours = false;
    Vec3 light = Vec3::UnitZ(); ///< unit
};

/// Checks the parts of the mesh rendering reads beyond check_model: one colour and one texture
/// coordinate per vertex (or none), all finite.
void check_appearance(const ModelMesh& mesh, Diagnostics& out)
{
    const size_t n = mesh.vertices.size();
    auto per_vertex = [&](size_t count, const char* what) {
        if (count != 0 && count != n)
            out.push_back(Diagnostic::error(DiagnosticCode::degenerate_model,
                                            model_name(mesh) + ": " + std::to_string(count) + " " +
                                                what + " for " + std::to_string(n) +
                                                " vertices, must be one per vertex or none",
                                            about_parameter(what)));
    };
    per_vertex(mesh.colours.size(), "colours");
    per_vertex(mesh.uvs.size(), "uvs");
    for (size_t i = 0; i < mesh.colours.size(); ++i)
        if (!mesh.colours[i].allFinite()) {
            out.push_back(Diagnostic::error(DiagnosticCode::non_finite_model,
                                            model_name(mesh) + ": colour of vertex " +
                                                std::to_string(i) + " is not finite",
                                            about_parameter("colours")));
            break;
        }
    // (NaN, NaN) is ModelMesh's mark for a vertex whose material has no texture (model_mesh.hpp):
    // such corners are coloured from `colours` or the shaded base colour. Anything else not
    // finite is an error.
    for (size_t i = 0; i < mesh.uvs.size(); ++i)
        if (!mesh.uvs[i].allFinite() && !mesh.uvs[i].array().isNaN().all()) {
            out.push_back(Diagnostic::error(DiagnosticCode::non_finite_model,
                                            model_name(mesh) + ": texture coordinate of vertex " +
                                                std::to_string(i) + " is not finite",
                                            about_parameter("uvs")));
            break;
        }
    if (!mesh.base_colour.allFinite())
        out.push_back(Diagnostic::error(DiagnosticCode::non_finite_model,
                                        model_name(mesh) + ": base colour is not finite",
                                        about_parameter("base_colour")));
}

Result<Appearance> prepare(const ModelMesh& mesh, const ArtworkOptions& options)
{
    Result<Appearance> r;
    r.diagnostics = check_artwork_options(options);
    const Result<ModelMesh> checked = check_model(mesh);
    r.diagnostics.insert(r.diagnostics.end(), checked.diagnostics.begin(),
                         checked.diagnostics.end());
    if (checked.ok)
        check_appearance(mesh, r.diagnostics);
    if (has_errors(r.diagnostics)) {
        r.ok = false;
        return r;
    }
    r.value.light = options.light.normalized();
    r.value.vertex_colours = !mesh.colours.empty();
    if (!mesh.texture.empty()) {
        const std::string fallback =
            r.value.vertex_colours ? "vertex colours are used" : "the shaded base colour is used";
        if (mesh.uvs.empty()) {
            r.warn(DiagnosticCode::unreadable_texture,
                   model_name(mesh) + ": texture " + mesh.texture +
                       " has no texture coordinates to map it; " + fallback,
                   about_parameter("uvs"));
        } else {
            Result<RgbaImage> image = read_model_texture(mesh);
            if (image.ok)
                r.value.texture = std::move(image.value);
            else
                for (const Diagnostic& d : image.diagnostics)
                    r.warn(d.code, d.message + "; " + fallback, about_parameter("texture"));
        }
    }
    return r;
}

std::uint8_t channel(double value)
{
    return std::uint8_t(std::lround(std::clamp(value, 0.0, 1.0) * 255.0));
}

/// Bilinear sample of a repeating texture; v = 0 is the bottom row (OpenGL, assimp).
std::array<double, 4> sample(const RgbaImage& texture, const Vec2& uv)
{
    const double u = uv.x() - std::floor(uv.x()), v = uv.y() - std::floor(uv.y());
    const double x = u * texture.width - 0.5, y = (1.0 - v) * texture.height - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    const double tx = x - fx, ty = y - fy;
    auto wrap = [](long long i, int n) { return int(((i % n) + n) % n); };
    const int x0 = wrap((long long)fx, texture.width), x1 = wrap((long long)fx + 1, texture.width);
    const int y0 = wrap((long long)fy, texture.height),
              y1 = wrap((long long)fy + 1, texture.height);
    std::array<double, 4> out{};
    for (int k = 0; k < 4; ++k)
        out[k] =
            ((1 - tx) * (1 - ty) * texture.at(x0, y0)[k] + tx * (1 - ty) * texture.at(x1, y0)[k] +
             (1 - tx) * ty * texture.at(x0, y1)[k] + tx * ty * texture.at(x1, y1)[k]) /
            255.0;
    return out;
}

/// A model vertex in the patch frame: (u, v) on the patch, d its height towards the viewer.
struct Projected {
    double a = 0.0, b = 0.0, d = 0.0;
};

/// Barycentric weights of (a, b) in triangle p, given twice its signed area.
std::array<double, 3> weights(const std::array<Projected, 3>& p, double twice_area, double a,
                              double b)
{
    auto edge = [&](const Projected& from, const Projected& to) {
        return (to.a - from.a) * (b - from.b) - (to.b - from.b) * (a - from.a);
    };
    const double w0 = edge(p[1], p[2]) / twice_area;
    const double w1 = edge(p[2], p[0]) / twice_area;
    return {w0, w1, 1.0 - w0 - w1};
}

/// The pixels of an artwork: the patch's bounding box from `lo` in steps of `step` mm, row 0
/// at the top.
struct PixelGrid {
    Vec2 lo = Vec2::Zero();
    double step = 1.0;
    int width = 0, height = 0;

    double centre_u(int column) const { return lo.x() + (column + 0.5) * step; }
    double centre_v(int row) const { return lo.y() + (height - row - 0.5) * step; }
};

/// Pass 1: the z-buffer keeps, per pixel, the triangle nearest the viewer within the window;
/// per pixel (row by row) its triangle, or -1.
std::vector<int> nearest_triangles(const ModelMesh& mesh, const std::vector<Projected>& projected,
                                   const Vec3& view, const PixelGrid& grid,
                                   const ArtworkOptions& options)
{
    const Vec2 lo = grid.lo;
    const double step = grid.step;
    const int width = grid.width, height = grid.height;
    std::vector<float> nearest(size_t(width) * height, -INFINITY); // float: half the memory
    std::vector<int> owner(size_t(width) * height, -1);
    constexpr double inside = -1e-9; // weights this far below 0 still count: no cracks
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        const Vec3 n = (mesh.vertices[tri[1]] - mesh.vertices[tri[0]])
                           .cross(mesh.vertices[tri[2]] - mesh.vertices[tri[0]]);
        if (!(n.dot(view) > 0.0))
            continue; // back-facing or edge-on: the viewer sees another surface there
        const std::array<Projected, 3> p{projected[tri[0]], projected[tri[1]], projected[tri[2]]};
        const double d_min = std::min({p[0].d, p[1].d, p[2].d});
        const double d_max = std::max({p[0].d, p[1].d, p[2].d});
        if (d_max < -options.behind || d_min > options.depth)
            continue;
        const double twice_area =
            (p[1].a - p[0].a) * (p[2].b - p[0].b) - (p[2].a - p[0].a) * (p[1].b - p[0].b);
        if (twice_area == 0.0)
            continue;
        const double a_min = std::min({p[0].a, p[1].a, p[2].a});
        const double a_max = std::max({p[0].a, p[1].a, p[2].a});
        const double b_min = std::min({p[0].b, p[1].b, p[2].b});
        const double b_max = std::max({p[0].b, p[1].b, p[2].b});
        // Pixels whose centres can fall inside: centre_u(c) in [a_min, a_max], likewise rows.
        // Clamped as doubles first: a triangle far off the patch must not overflow an int.
        auto index = [](double x, int n) { return int(std::clamp(x, -1.0, double(n))); };
        const int c0 = std::max(0, index(std::ceil((a_min - lo.x()) / step - 0.5), width) - 1);
        const int c1 =
            std::min(width - 1, index(std::floor((a_max - lo.x()) / step - 0.5), width) + 1);
        const int r0 =
            std::max(0, index(std::ceil(height - 0.5 - (b_max - lo.y()) / step), height) - 1);
        const int r1 = std::min(
            height - 1, index(std::floor(height - 0.5 - (b_min - lo.y()) / step), height) + 1);
        for (int row = r0; row <= r1; ++row)
            for (int column = c0; column <= c1; ++column) {
                const auto w = weights(p, twice_area, grid.centre_u(column), grid.centre_v(row));
                if (w[0] < inside || w[1] < inside || w[2] < inside)
                    continue;
                const double d = w[0] * p[0].d + w[1] * p[1].d + w[2] * p[2].d;
                const size_t k = size_t(row) * width + column;
                // Compared as stored, so an equally near later triangle never wins.
                if (d < -options.behind || d > options.depth || !(float(d) > nearest[k]))
                    continue;
                nearest[k] = float(d);
                owner[k] = int(t);
            }
    }
    return owner;
}

/// Pass 2: colour each pixel once, from its triangle (`owner`, from nearest_triangles).
void colour_pixels(const ModelMesh& mesh, const Appearance& look,
                   const std::vector<Projected>& projected, const std::vector<int>& owner,
                   const PixelGrid& grid, const ArtworkOptions& options, PatchArtwork& art)
{
    const int width = grid.width, height = grid.height;
    for (int row = 0; row < height; ++row)
        for (int column = 0; column < width; ++column) {
            const int t = owner[size_t(row) * width + column];
            if (t < 0)
                continue;
            const auto& tri = mesh.triangles[t];
            const std::array<Projected, 3> p{projected[tri[0]], projected[tri[1]],
                                             projected[tri[2]]};
            const double twice_area =
                (p[1].a - p[0].a) * (p[2].b - p[0].b) - (p[2].a - p[0].a) * (p[1].b - p[0].b);
            auto w = weights(p, twice_area, grid.centre_u(column), grid.centre_v(row));
            for (double& x : w)
                x = std::max(x, 0.0);
            const double sum = w[0] + w[1] + w[2];
            for (double& x : w)
                x /= sum;
            std::uint8_t* out = art.image.at(column, row);
            if (look.texture && mesh.uvs[tri[0]].allFinite() && mesh.uvs[tri[1]].allFinite() &&
                mesh.uvs[tri[2]].allFinite()) {
                const Vec2 uv =
                    w[0] * mesh.uvs[tri[0]] + w[1] * mesh.uvs[tri[1]] + w[2] * mesh.uvs[tri[2]];
                const auto texel = sample(*look.texture, uv);
                for (int k = 0; k < 4; ++k)
                    out[k] = channel(texel[k]);
            } else {
                Vec3 colour;
                if (look.vertex_colours) {
                    colour = w[0] * mesh.colours[tri[0]] + w[1] * mesh.colours[tri[1]] +
                             w[2] * mesh.colours[tri[2]];
                } else {
                    const Vec3 n = (mesh.vertices[tri[1]] - mesh.vertices[tri[0]])
                                       .cross(mesh.vertices[tri[2]] - mesh.vertices[tri[0]])
                                       .normalized();
                    const double lit = options.ambient +
                                       (1.0 - options.ambient) * std::max(0.0, n.dot(look.light));
                    colour = lit * mesh.base_colour;
                }
                for (int k = 0; k < 3; ++k)
                    out[k] = channel(colour[k]);
                out[3] = 255;
            }
            ++art.covered_pixels;
        }
}

Result<PatchArtwork> render_one(const ModelMesh& mesh, const Appearance& look, const Patch& given,
                                const ArtworkOptions& options)
{
    Result<PatchArtwork> r;
    Patch patch = given; // the frame is always the one derive_frame gives, as the sheets use
    const double deviation = patch.derive_frame();
    Loop2 outline = patch.outer_local();
    Vec2 lo = Vec2::Constant(INFINITY), hi = Vec2::Constant(-INFINITY);
    for (const Vec2& p : outline) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    if (!std::isfinite(deviation) || outline.size() < 3 || !(patch.area() > 0.0) ||
        !lo.allFinite() || !hi.allFinite()) {
        r.fail(DiagnosticCode::degenerate_patch,
               patch_subject(given) +
                   ": its outline encloses no area, there is nothing to print on",
               about_patches({given.id}));
        return r;
    }
    const double tolerance = 1e-4 * std::max((hi - lo).norm(), 1.0);
    if (deviation > tolerance) {
        r.fail(DiagnosticCode::non_planar_patch,
               patch_subject(given) + ": not planar, a vertex lies " + number(deviation) +
                   " mm off its plane (allowed " + number(tolerance) + " mm)",
               about_patches({given.id}));
        return r;
    }
    const double step = 1.0 / options.pixels_per_mm;
    const double columns = std::max(1.0, std::ceil((hi.x() - lo.x()) * options.pixels_per_mm));
    const double rows = std::max(1.0, std::ceil((hi.y() - lo.y()) * options.pixels_per_mm));
    if (columns * rows > double(options.max_pixels)) {
        r.fail(DiagnosticCode::bad_option,
               "artwork of " + patch_subject(given) + ": " + whole(columns) + " x " + whole(rows) +
                   " pixels at " + number(options.pixels_per_mm) +
                   " pixels per mm, at most max_pixels = " + std::to_string(options.max_pixels) +
                   "; lower pixels_per_mm",
               about_parameter("pixels_per_mm"));
        return r;
    }
    const int width = int(columns), height = int(rows);

    PatchArtwork& art = r.value;
    art.patch = given.id;
    art.origin = lo;
    art.mm_per_pixel = step;
    art.back_side = options.back_side;
    art.frame_origin = patch.origin;
    art.frame_u = patch.u;
    art.frame_v = patch.v;
    art.frame_normal = patch.normal;
    art.image.width = width;
    art.image.height = height;
    art.image.pixels.assign(size_t(4) * width * height, 0);

    const double toward_viewer = options.back_side ? -1.0 : 1.0;
    const Vec3 view = toward_viewer * patch.normal;
    std::vector<Projected> projected(mesh.vertices.size());
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        const Vec3 x = mesh.vertices[i] - patch.origin;
        projected[i] = {x.dot(patch.u), x.dot(patch.v), toward_viewer * x.dot(patch.normal)};
    }
    const PixelGrid grid{lo, step, width, height};
    const std::vector<int> owner = nearest_triangles(mesh, projected, view, grid, options);
    colour_pixels(mesh, look, projected, owner, grid, options, art);
    return r;
}

} // namespace

Diagnostics check_artwork_options(const ArtworkOptions& o)
{
    Diagnostics out;
    auto refuse = [&](const char* option, const std::string& value, const std::string& allowed) {
        out.push_back(Diagnostic::error(DiagnosticCode::bad_option,
                                        std::string("artwork: ") + option + " = " + value +
                                            ", must be " + allowed,
                                        about_parameter(option)));
    };
    if (!(o.pixels_per_mm > 0.0 && o.pixels_per_mm <= kMaxPixelsPerMm))
        refuse("pixels_per_mm", number(o.pixels_per_mm),
               "> 0 and at most " + number(kMaxPixelsPerMm) + " (1016 dpi)");
    if (!(o.depth > 0.0))
        refuse("depth", number(o.depth), "> 0 mm (inf for no limit)");
    if (!(o.behind >= 0.0 && std::isfinite(o.behind)))
        refuse("behind", number(o.behind), ">= 0 mm and finite");
    if (!(o.ambient >= 0.0 && o.ambient <= 1.0))
        refuse("ambient", number(o.ambient), "in [0, 1]");
    if (!o.light.allFinite() || o.light.norm() == 0.0)
        refuse("light",
               "(" + number(o.light.x()) + ", " + number(o.light.y()) + ", " + number(o.light.z()) +
                   ")",
               "a finite, non-zero direction");
    if (!(o.max_pixels >= 1 && o.max_pixels <= kMaxPixelsCap))
        refuse("max_pixels", std::to_string(o.max_pixels),
               "in [1, " + std::to_string(kMaxPixelsCap) + "]");
    return out;
}

Result<std::vector<PatchArtwork>> render_artworks(const ModelMesh& mesh,
                                                  const std::vector<Patch>& patches,
                                                  const ArtworkOptions& options)
{
    Result<std::vector<PatchArtwork>> r;
    const Result<Appearance> look = prepare(mesh, options);
    r.diagnostics = look.diagnostics;
    if (!look.ok) {
        r.ok = false;
        return r;
    }
    // Each patch's image is its own: two are rendered at a time (two cores), then taken in
    // order, the first failure the answer as when they were rendered one after the other.
    std::vector<Result<PatchArtwork>> rendered(patches.size());
    std::atomic<std::size_t> next{0};
    auto render_next = [&] {
        for (std::size_t i; (i = next++) < patches.size();)
            rendered[i] = render_one(mesh, look.value, patches[i], options);
    };
    std::future<void> other = std::async(std::launch::async, render_next);
    render_next();
    other.get();
    for (Result<PatchArtwork>& one : rendered) {
        if (!one.ok) {
            r.fail_with(one.diagnostics);
            return r;
        }
        r.value.push_back(std::move(one.value));
    }
    return r;
}

Result<PatchArtwork> render_artwork(const ModelMesh& mesh, const Patch& patch,
                                    const ArtworkOptions& options)
{
    Result<std::vector<PatchArtwork>> all = render_artworks(mesh, {patch}, options);
    Result<PatchArtwork> r;
    r.ok = all.ok;
    r.diagnostics = std::move(all.diagnostics);
    if (all.ok)
        r.value = std::move(all.value.front());
    return r;
}

} // namespace popup
