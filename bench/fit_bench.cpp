// fit_design on meshes of about 10k, 30k and 100k vertices (goal: <= 0.5 s at 30k), and the
// primitive fitting next to CGAL's Efficient RANSAC of planes on the same pseudo-vertices
// (goal: <= 1.5x its time, coverage >= 0.95). The only translation unit of the fitting that
// includes CGAL.
#include <benchmark/benchmark.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Shape_detection/Efficient_RANSAC.h>

#include "fitting/synthetic_models.hpp"
#include "popup/fitting/alignment.hpp"
#include "popup/fitting/fit_design.hpp"
#include "popup/fitting/prism_ransac.hpp"
#include "popup/fitting/surface_samples.hpp"

namespace {

using namespace popup;

ModelMesh bench_model(int vertices)
{
    return testing::tessellated(testing::truck_model(), vertices);
}

void BM_FitDesign(benchmark::State& state)
{
    const ModelMesh model = bench_model(int(state.range(0)));
    const FitOptions options;
    double coverage = 0, mechanisms = 0, valid = 0;
    for (auto _ : state) {
        const auto r = fit_design(model, options);
        for (const auto& [stage, seconds] : r.value.timings.stages) // where the time goes
            state.counters["s_" + stage] = seconds;
        coverage = r.value.coverage;
        mechanisms = double(r.value.mechanisms.size());
        valid = r.value.valid;
        benchmark::DoNotOptimize(r.value.mechanisms.data());
    }
    state.counters["vertices"] = double(model.vertices.size());
    state.counters["mechanisms"] = mechanisms;
    state.counters["valid"] = valid;
    state.counters["coverage"] = coverage;
}
BENCHMARK(BM_FitDesign)->Arg(10000)->Arg(30000)->Arg(100000)->Unit(benchmark::kMillisecond);

/// The pseudo-vertices fit_design fits, in the card's frame, and the card's pair.
struct Prepared {
    SurfaceSamples samples;
    PrismHost card;
    RansacOptions options;
};

Prepared prepare(int vertices)
{
    const ModelMesh model = bench_model(vertices);
    const FitOptions o;
    Prepared p;
    const Result<Alignment> a =
        align_model(model, sample_surface(model, 4000, o.seed), o.up, o.facing, {o.card, o.margin});
    p.samples = transformed(sample_surface(model, o.samples, o.seed + 1), a.value.model_to_card);
    p.card.name = "central fold";
    p.card.length = o.card.width;
    p.card.across_min = -o.card.depth;
    p.card.across_max = o.card.depth;
    const double diagonal = a.value.scale * model.diagonal();
    const double tau = o.min_shape * diagonal;
    p.options.threshold = o.threshold * diagonal;
    p.options.min_points = std::max(8.0, 5 * tau * tau / (p.samples.spacing * p.samples.spacing));
    p.options.probability = o.probability;
    p.options.seed = o.seed;
    p.options.max_primitives = o.max_mechanisms;
    return p;
}

void BM_PrismRansac(benchmark::State& state)
{
    const Prepared p = prepare(30000);
    double coverage = 0, shapes = 0;
    for (auto _ : state) {
        const RansacResult r = fit_prisms(p.samples, p.card, p.options);
        size_t covered = 0;
        for (size_t i = 0; i < r.owner.size(); ++i)
            covered += r.owner[i] >= 0 || r.on_base[i];
        coverage = double(covered) / double(r.owner.size());
        shapes = double(r.prisms.size());
        benchmark::DoNotOptimize(r.prisms.data());
    }
    state.counters["points"] = double(p.samples.points.size());
    state.counters["shapes"] = shapes;
    state.counters["coverage"] = coverage;
}
BENCHMARK(BM_PrismRansac)->Unit(benchmark::kMillisecond);

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using PointWithNormal = std::pair<Kernel::Point_3, Kernel::Vector_3>;
using Points = std::vector<PointWithNormal>;
using Traits = CGAL::Shape_detection::Efficient_RANSAC_traits<
    Kernel, Points, CGAL::First_of_pair_property_map<PointWithNormal>,
    CGAL::Second_of_pair_property_map<PointWithNormal>>;
using EfficientRansac = CGAL::Shape_detection::Efficient_RANSAC<Traits>;
using Plane = CGAL::Shape_detection::Plane<Traits>;

/// The baseline: CGAL's Efficient RANSAC (Schnabel et al. 2007) detecting planes on the same
/// points, with the same ε, minimum size and probability.
void BM_CgalEfficientRansacPlanes(benchmark::State& state)
{
    const Prepared p = prepare(30000);
    Points points;
    for (size_t i = 0; i < p.samples.points.size(); ++i) {
        const Vec3& x = p.samples.points[i];
        const Vec3& n = p.samples.normals[i];
        points.push_back({{x.x(), x.y(), x.z()}, {n.x(), n.y(), n.z()}});
    }
    EfficientRansac::Parameters parameters;
    parameters.probability = 1 - p.options.probability;
    parameters.min_points = std::size_t(p.options.min_points);
    parameters.epsilon = p.options.threshold;
    parameters.cluster_epsilon = 4 * p.samples.spacing;
    parameters.normal_threshold = 0.94;
    double coverage = 0, shapes = 0;
    for (auto _ : state) {
        EfficientRansac ransac;
        ransac.set_input(points);
        ransac.add_shape_factory<Plane>();
        ransac.detect(parameters);
        shapes = double(ransac.shapes().size());
        coverage = 1.0 - double(ransac.number_of_unassigned_points()) / double(points.size());
    }
    state.counters["points"] = double(points.size());
    state.counters["shapes"] = shapes;
    state.counters["coverage"] = coverage;
}
BENCHMARK(BM_CgalEfficientRansacPlanes)->Unit(benchmark::kMillisecond);

} // namespace
