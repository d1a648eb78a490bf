// The artwork rasteriser on spheres of 10k, 30k and 100k vertices rendered onto a 100 x 100 mm
// patch at 300 dpi (1181 x 1181 pixels). Baseline in the same process: the same patch and image
// with the sphere out of the depth window, the fixed cost of allocating, clearing and scanning
// the image.
#include <benchmark/benchmark.h>

#include <cmath>

#include "popup/sheets/render_artwork.hpp"

using namespace popup;

namespace {

/// A UV sphere of about `vertices` vertices, radius 40 mm, standing on z = 0 at (50, 50), with
/// vertex colours from its normals.
ModelMesh sphere(int vertices)
{
    const int rings = int(std::sqrt(vertices / 2.0));
    const int segments = 2 * rings;
    const double pi = std::acos(-1.0);
    ModelMesh m;
    m.source = "sphere";
    for (int i = 0; i <= rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const double theta = pi * i / rings, phi = 2 * pi * j / segments;
            const Vec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                         std::cos(theta));
            m.vertices.push_back(Vec3(50, 50, 40) + 40.0 * n);
            m.colours.push_back(0.5 * (n + Vec3::Ones()));
        }
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const int a = i * segments + j, b = i * segments + (j + 1) % segments;
            const int c = a + segments, d = b + segments;
            m.triangles.push_back({a, c, d}); // counter-clockwise seen from outside
            m.triangles.push_back({a, d, b});
        }
    return m;
}

Patch patch_at(double z)
{
    Patch p;
    p.id = 1;
    p.outer = {{0, 0, z}, {100, 0, z}, {100, 100, z}, {0, 100, z}};
    p.derive_frame();
    return p;
}

void render(benchmark::State& state, double window)
{
    const ModelMesh mesh = sphere(int(state.range(0)));
    const Patch top = patch_at(80.0); // tangent to the sphere's top
    ArtworkOptions o;
    o.depth = 1.0;
    o.behind = window; // 80 mm: the whole upper half; 0: nothing but the top point
    long long covered = 0;
    for (auto _ : state) {
        const Result<PatchArtwork> r = render_artwork(mesh, top, o);
        covered = r.value.covered_pixels;
        benchmark::DoNotOptimize(r.value.image.pixels.data());
    }
    state.counters["vertices"] = double(mesh.vertices.size());
    state.counters["covered_pixels"] = double(covered);
}

void BM_RenderArtworkSphere(benchmark::State& state)
{
    render(state, 80.0);
}

void BM_RenderArtworkEmptyWindowBaseline(benchmark::State& state)
{
    render(state, 0.0);
}

} // namespace

BENCHMARK(BM_RenderArtworkSphere)
    ->Unit(benchmark::kMillisecond)
    ->Arg(10000)
    ->Arg(30000)
    ->Arg(100000);
BENCHMARK(BM_RenderArtworkEmptyWindowBaseline)
    ->Unit(benchmark::kMillisecond)
    ->Arg(10000)
    ->Arg(30000)
    ->Arg(100000);
