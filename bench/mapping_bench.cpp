// The mapping stage on a long capture's path (thesis §6.2–6.3): fit_candidates on a chain of
// 8000 adaptive samples (a 4511-frame BVH keeps ~8000), its fits evaluating every k-th sample
// (search_target, at most fit_samples_max), against the same-process baseline whose fits
// evaluate all of them. Counter error_mm: the rotation candidate's eq 6.6 error over all
// samples (the thinned fit must stay as close as the baseline's).
#include <benchmark/benchmark.h>

#include <cmath>
#include <limits>

#include "motion/chain_mapping.hpp"
#include "motion/motion_kinematics.hpp"
#include "motion/motion_parameters.hpp"

namespace {

using namespace popup;
using namespace popup::motion;

// A rotation arm's tip over 8000 samples with a 1 mm wobble along the fold (capture jitter).
ChainTarget long_path()
{
    const MotionMechanism arm = rotation_mechanism(60, 40, 30, 25);
    ChainTarget t;
    t.weight = 1;
    for (int k = 0; k < 8000; ++k) {
        const double s = k / 7999.0;
        t.s.push_back(s);
        t.target.push_back(mechanism_point(arm, M_PI * s).head<2>() + Vec2(0, std::sin(0.9 * k)));
    }
    return t;
}

void run(benchmark::State& state, std::size_t fit_samples)
{
    const ChainTarget t = long_path();
    CardParams card;
    card.width = 210;
    card.depth = 148;
    double error = 0;
    for (auto _ : state) {
        const auto candidates = fit_candidates(t, card, 25, fit_samples);
        error = candidates[int(MotionKind::rotation)].error_mm;
        benchmark::DoNotOptimize(error);
    }
    state.counters["error_mm"] = error;
}

void BM_MappingLongPathThinned(benchmark::State& state)
{
    run(state, fit_samples_max);
}
void BM_MappingLongPathAllSamples(benchmark::State& state)
{
    run(state, std::numeric_limits<std::size_t>::max());
}

} // namespace

BENCHMARK(BM_MappingLongPathThinned)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MappingLongPathAllSamples)->Unit(benchmark::kMillisecond);
