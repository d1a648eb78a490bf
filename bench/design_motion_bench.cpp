// design_motion, the whole pipeline of issue 13 (chains, paths, mapping, annealing, build,
// validity), on generated characters of 4, 8 and 16 arms (goal: <= 1 s at <= 16 mechanisms; the
// thesis took "a few seconds"), next to its input stage alone (motion_targets) in the same process.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "popup/motion/design_motion.hpp"

namespace {

using namespace popup;

/// A body on the central fold with `arms` two-bone arms whose shoulders sit along the fold on
/// both pages; each arm turns in the card plane (file x right, y up, z toward the viewer): some
/// swing about the shoulder, some bend at the elbow, some do both, in either direction.
Animation generated_character(int arms, int frames = 61)
{
    Animation a;
    a.source = "generated character (" + std::to_string(arms) + " arms)";
    a.bones.push_back({"Body", -1});
    for (int i = 0; i < arms; ++i) {
        const int arm = int(a.bones.size());
        a.bones.push_back({"Arm" + std::to_string(i), 0});
        a.bones.push_back({"Fore" + std::to_string(i), arm});
        a.bones.push_back({"Hand" + std::to_string(i), arm + 1});
    }
    const Vec3 body(0.0, 100.0, 0.0);
    for (int f = 0; f < frames; ++f) {
        const double s = double(f) / (frames - 1);
        a.frame_times_s.push_back(f / 30.0);
        std::vector<Eigen::Isometry3d> local(a.bones.size(), Eigen::Isometry3d::Identity());
        local[0].translation() = body;
        for (int i = 0; i < arms; ++i) {
            const double side = i % 2 == 0 ? 1.0 : -1.0; // ground page, backdrop page
            const double along = 10.0 + 190.0 * (i / 2 + 0.5) / ((arms + 1) / 2);
            const Vec3 shoulder(side * (15.0 + 10.0 * (i % 3)), along, 2.0 + i);
            const double length = 18.0 + 2.0 * (i % 4);
            const double swing = (i % 3 == 1 ? 0.0 : 1.0) * (i % 4 < 2 ? 1.0 : -1.0) * 0.9 * s;
            const double bend = (i % 3 == 0 ? 0.0 : 1.0) * 0.7 * s;
            const double rest = side > 0 ? 0.0 : M_PI;
            const int b = 1 + 3 * i;
            local[b].translation() = shoulder - body;
            local[b].linear() = Eigen::AngleAxisd(rest + swing, Vec3::UnitZ()).toRotationMatrix();
            local[b + 1].translation() = Vec3(length, 0, 0);
            local[b + 1].linear() = Eigen::AngleAxisd(bend, Vec3::UnitZ()).toRotationMatrix();
            local[b + 2].translation() = Vec3(length, 0, 0);
        }
        a.local.push_back(local);
    }
    a.bind_inverse.assign(a.bones.size(), Eigen::Isometry3d::Identity());
    return a;
}

void BM_MotionTargets(benchmark::State& state)
{
    const Animation a = generated_character(int(state.range(0)));
    const MotionView view;
    double chains = 0;
    for (auto _ : state) {
        const auto r = motion_targets(a, view);
        chains = double(r.value.chains.size());
        benchmark::DoNotOptimize(r.value.paths.data());
    }
    state.counters["chains"] = chains;
}
BENCHMARK(BM_MotionTargets)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond);

void BM_DesignMotion(benchmark::State& state)
{
    const Animation a = generated_character(int(state.range(0)));
    const MotionOptions options;
    double mechanisms = 0, valid = 0, error = 0, animated = 0;
    std::vector<std::pair<std::string, double>> timings;
    for (auto _ : state) {
        const auto r = design_motion(a, options);
        if (!r.ok) {
            state.SkipWithError(r.diagnostics.empty() ? "design_motion failed"
                                                      : r.diagnostics.front().message.c_str());
            return;
        }
        mechanisms = double(r.value.mechanisms.size());
        valid = r.value.valid;
        error = r.value.weighted_error;
        animated = 0;
        for (const ChainReport& c : r.value.chains)
            animated += c.status != "stationary";
        timings = r.value.timings.stages;
        benchmark::DoNotOptimize(r.value.mechanisms.data());
    }
    state.counters["chains"] = double(a.bones.size() - 1) / 3.0;
    state.counters["mechanisms"] = mechanisms;
    state.counters["moving_chains"] = animated;
    state.counters["valid"] = valid;
    state.counters["weighted_error"] = error;
    for (const auto& [stage, seconds] : timings)
        state.counters["s_" + stage] = seconds;
}
BENCHMARK(BM_DesignMotion)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond);

} // namespace
