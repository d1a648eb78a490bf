// A model's silhouette on a patch: the core's union of the triangles' cancelled boundaries
// (silhouette_profile) against the baseline of uniting the projected triangles themselves with
// Clipper, on the same UV spheres seen from above the card's ground. "area_error" is the
// difference from the other method's area (mm²): the two must agree.
#include <benchmark/benchmark.h>

#include <cmath>

#include <polyclipping/clipper.hpp>

#include "popup/fitting/silhouette.hpp"
#include "popup/model/card.hpp"

namespace {

// A UV sphere (radius 20 mm) with `rings` rings: 4 · rings² triangles.
popup::ModelMesh sphere(int rings)
{
    popup::ModelMesh m;
    const int around = 2 * rings;
    const double pi = 3.14159265358979323846;
    for (int i = 0; i <= rings; ++i)
        for (int j = 0; j < around; ++j) {
            const double t = pi * i / rings, p = 2 * pi * j / around;
            m.vertices.emplace_back(50 + 20 * std::sin(t) * std::cos(p),
                                    100 + 20 * std::sin(t) * std::sin(p), 30 + 20 * std::cos(t));
        }
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < around; ++j) {
            const int a = i * around + j, b = i * around + (j + 1) % around;
            m.triangles.push_back({a, a + around, b + around});
            m.triangles.push_back({a, b + around, b});
        }
    return m;
}

popup::Scaffold card()
{
    return popup::make_card(popup::CardParams()).value;
}

// The baseline: every triangle projected onto the ground (z dropped) and united by Clipper.
double triangle_union_area(const popup::ModelMesh& m)
{
    ClipperLib::Paths paths;
    for (const auto& t : m.triangles) {
        ClipperLib::Path path;
        for (int k : t)
            path.push_back({static_cast<ClipperLib::cInt>(std::llround(m.vertices[k].x() * 1e6)),
                            static_cast<ClipperLib::cInt>(std::llround(m.vertices[k].y() * 1e6))});
        if (!ClipperLib::Orientation(path))
            ClipperLib::ReversePath(path);
        paths.push_back(path);
    }
    ClipperLib::Clipper c;
    c.AddPaths(paths, ClipperLib::ptSubject, true);
    ClipperLib::Paths out;
    c.Execute(ClipperLib::ctUnion, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    double area = 0;
    for (const auto& p : out)
        area += ClipperLib::Area(p) / 1e12;
    return area;
}

void BM_SilhouetteBoundaryUnion(benchmark::State& state)
{
    const popup::ModelMesh m = sphere(static_cast<int>(state.range(0)));
    const popup::Scaffold s = card();
    double area = 0;
    for (auto _ : state)
        area = popup::silhouette_profile(m, s, s.ground).value.area;
    state.counters["triangles"] = static_cast<double>(m.triangles.size());
    if (state.range(0) <= 50)
        state.counters["area_error"] = std::abs(area - triangle_union_area(m));
}

void BM_SilhouetteTriangleUnion(benchmark::State& state)
{
    const popup::ModelMesh m = sphere(static_cast<int>(state.range(0)));
    for (auto _ : state)
        benchmark::DoNotOptimize(triangle_union_area(m));
    state.counters["triangles"] = static_cast<double>(m.triangles.size());
}

} // namespace

// 2.5k to 160k triangles for the core; the baseline up to 10k.
BENCHMARK(BM_SilhouetteBoundaryUnion)
    ->Arg(25)
    ->Arg(50)
    ->Arg(100)
    ->Arg(200)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SilhouetteTriangleUnion)
    ->Arg(25)
    ->Arg(50)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
