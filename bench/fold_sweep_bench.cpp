// Fold sweep, validity check and BREP export against the patch count. BM_SweepNaiveSteps is the
// same-process baseline for BM_SimulateSweep: the same 181 angles, one simulate_fold call each,
// so every call restarts the continuation from the design state. The ...Dense rows are the
// baseline of the sparse solver: the same check with dense normal equations.
#include <benchmark/benchmark.h>
#include <tbb/task_arena.h>

#include <string>
#include <vector>

#include "generated_scaffolds.hpp"
#include "popup/io/brep_export.hpp"
#include "popup/simulation/check_validity.hpp"
#include "popup/simulation/simulate_fold.hpp"

namespace {

using popup::fixtures::generated_scaffold;

constexpr int kAngles = 181;

/// 180° down to 0° in 1° steps: the order the card closes in, which continuation follows.
std::vector<double> sweep_angles()
{
    constexpr double pi = 3.14159265358979323846;
    std::vector<double> angles(kAngles);
    for (int k = 0; k < kAngles; ++k)
        angles[k] = pi * (kAngles - 1 - k) / (kAngles - 1);
    return angles;
}

void set_counters(benchmark::State& state, const popup::Scaffold& scaffold)
{
    state.counters["patches"] = static_cast<double>(scaffold.patches.size());
    state.counters["hinges"] = static_cast<double>(scaffold.hinges.size());
}

void BM_SimulateSweep(benchmark::State& state)
{
    const popup::Scaffold scaffold = generated_scaffold(static_cast<int>(state.range(0)));
    const std::vector<double> angles = sweep_angles();
    for (auto _ : state) {
        popup::Result<popup::FoldSweep> sweep = popup::simulate_fold(scaffold, angles);
        if (!sweep.ok || !sweep.value.complete) {
            state.SkipWithError("simulate_fold did not reach every angle");
            break;
        }
        benchmark::DoNotOptimize(sweep.value.states.data());
    }
    set_counters(state, scaffold);
    state.counters["angles"] = kAngles;
}

void BM_SweepNaiveSteps(benchmark::State& state)
{
    const popup::Scaffold scaffold = generated_scaffold(static_cast<int>(state.range(0)));
    const std::vector<double> angles = sweep_angles();
    for (auto _ : state) {
        for (double angle : angles) {
            popup::Result<popup::FoldSweep> sweep = popup::simulate_fold(scaffold, {angle});
            if (!sweep.ok || !sweep.value.complete) {
                state.SkipWithError("simulate_fold did not reach an angle");
                return;
            }
            benchmark::DoNotOptimize(sweep.value.states.data());
        }
    }
    set_counters(state, scaffold);
    state.counters["angles"] = kAngles;
}

void BM_CheckValidity(benchmark::State& state)
{
    const popup::Scaffold scaffold = generated_scaffold(static_cast<int>(state.range(0)));
    bool valid = false;
    for (auto _ : state) {
        popup::ValidityReport report = popup::check_validity(scaffold);
        valid = report.valid();
        benchmark::DoNotOptimize(valid);
    }
    set_counters(state, scaffold);
    // Timing an invalid verdict would measure an early exit: report it next to the time.
    state.counters["valid"] = valid ? 1.0 : 0.0;
}

/// BM_CheckValidity's baseline in the same process: the same check confined to one thread (the
/// simulator follows independent components, and their stability, on all cores).
void BM_CheckValiditySerial(benchmark::State& state)
{
    const popup::Scaffold scaffold = generated_scaffold(static_cast<int>(state.range(0)));
    tbb::task_arena one_thread(1);
    bool valid = false;
    for (auto _ : state) {
        one_thread.execute([&] { valid = popup::check_validity(scaffold).valid(); });
        benchmark::DoNotOptimize(valid);
    }
    set_counters(state, scaffold);
    state.counters["valid"] = valid ? 1.0 : 0.0;
}

/// check_validity of `scaffold` with the default solver, or with dense normal equations
/// (SimulationOptions::dense_linear_algebra): the same-process baseline of the sparse solver.
void check_validity_rows(benchmark::State& state, const popup::Scaffold& scaffold, bool dense)
{
    popup::ValidityOptions options;
    options.dense_linear_algebra = dense;
    bool valid = false;
    for (auto _ : state) {
        popup::ValidityReport report = popup::check_validity(scaffold, options);
        valid = report.valid();
        benchmark::DoNotOptimize(valid);
    }
    set_counters(state, scaffold);
    state.counters["valid"] = valid ? 1.0 : 0.0;
}

/// A box whose ends are made of `panel_pairs` stacked strips (issue 10: 10 pairs took 17.7 s):
/// how the validity check grows with the panels of one mechanism.
void BM_CheckValidityBoxPanelPairs(benchmark::State& state)
{
    check_validity_rows(state, popup::fixtures::box_with_panel_pairs(int(state.range(0))), false);
}

void BM_CheckValidityBoxPanelPairsDense(benchmark::State& state)
{
    check_validity_rows(state, popup::fixtures::box_with_panel_pairs(int(state.range(0))), true);
}

/// `depth` boxes each standing on the top of the one below (issue 10: 10 took 28.8 s): how the
/// check grows with the bodies of one connected mechanism (9 per box). The Dense rows are the
/// solver before sparse factorisation, whose normal equations grew with the cube of the bodies.
void BM_CheckValidityNestedBoxes(benchmark::State& state)
{
    check_validity_rows(state, popup::fixtures::nested_boxes(int(state.range(0))), false);
}

void BM_CheckValidityNestedBoxesDense(benchmark::State& state)
{
    check_validity_rows(state, popup::fixtures::nested_boxes(int(state.range(0))), true);
}

/// The tent card with its ground outline split into `vertices` points along its four edges, as
/// outlines from models are: the validity check must stay near-linear in the vertex count.
void BM_CheckValidityLongOutline(benchmark::State& state)
{
    popup::Scaffold scaffold = generated_scaffold(1);
    popup::Patch& ground = scaffold.patches[scaffold.patch_index(scaffold.ground)];
    const popup::Loop3 corners = ground.outer;
    const int per_edge = static_cast<int>(state.range(0)) / int(corners.size());
    ground.outer.clear();
    for (size_t k = 0; k < corners.size(); ++k)
        for (int i = 0; i < per_edge; ++i)
            ground.outer.push_back(corners[k] + (corners[(k + 1) % corners.size()] - corners[k]) *
                                                    (double(i) / per_edge));
    popup::ValidityOptions options;
    options.samples = 19;
    bool valid = false;
    for (auto _ : state) {
        valid = popup::check_validity(scaffold, options).valid();
        benchmark::DoNotOptimize(valid);
    }
    state.counters["vertices"] = double(ground.outer.size());
    state.counters["valid"] = valid ? 1.0 : 0.0;
}

void BM_PatchesToBrep(benchmark::State& state)
{
    const popup::Scaffold scaffold = generated_scaffold(static_cast<int>(state.range(0)));
    constexpr double half_open = 3.14159265358979323846 / 2.0;
    popup::Result<popup::FoldSweep> sweep = popup::simulate_fold(scaffold, {half_open});
    if (!sweep.ok || sweep.value.states.size() != 1) {
        state.SkipWithError("simulate_fold failed at 90 degrees");
        return;
    }
    const popup::FoldState& fold_state = sweep.value.states.front();
    std::size_t bytes = 0;
    for (auto _ : state) {
        std::string brep = popup::patches_to_brep(scaffold, fold_state);
        bytes = brep.size();
        benchmark::DoNotOptimize(brep.data());
    }
    set_counters(state, scaffold);
    state.counters["brep_kB"] = static_cast<double>(bytes) / 1024.0;
}

} // namespace

BENCHMARK(BM_SimulateSweep)->Unit(benchmark::kMillisecond)->Arg(10)->Arg(50)->Arg(100)->Arg(200);
BENCHMARK(BM_SweepNaiveSteps)->Unit(benchmark::kMillisecond)->Arg(10)->Arg(50)->Arg(100)->Arg(200);
BENCHMARK(BM_CheckValidity)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Arg(10)
    ->Arg(50)
    ->Arg(100)
    ->Arg(200);
BENCHMARK(BM_CheckValiditySerial)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Arg(10)
    ->Arg(50)
    ->Arg(100)
    ->Arg(200);
BENCHMARK(BM_CheckValidityBoxPanelPairs)->Unit(benchmark::kMillisecond)->Arg(1)->Arg(4)->Arg(10);
BENCHMARK(BM_CheckValidityBoxPanelPairsDense)
    ->Unit(benchmark::kMillisecond)
    ->Arg(1)
    ->Arg(4)
    ->Arg(10);
BENCHMARK(BM_CheckValidityNestedBoxes)->Unit(benchmark::kMillisecond)->Arg(2)->Arg(5)->Arg(10);
BENCHMARK(BM_CheckValidityNestedBoxesDense)->Unit(benchmark::kMillisecond)->Arg(2)->Arg(5)->Arg(10);
BENCHMARK(BM_CheckValidityLongOutline)
    ->Unit(benchmark::kMillisecond)
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(100000)
    ->Iterations(1);
BENCHMARK(BM_PatchesToBrep)->Unit(benchmark::kMillisecond)->Arg(10)->Arg(50)->Arg(100)->Arg(200);

BENCHMARK_MAIN();
