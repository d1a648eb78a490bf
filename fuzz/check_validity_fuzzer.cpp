// libFuzzer target 2: check_validity on small random scaffolds. The bytes choose a card, up to
// three mechanisms from the generators (each on the central fold or on a base patch pair an
// earlier one offers), their parameters (now and then NaN, an infinity, zero, a negative or a
// huge value), and a few perturbations of the result (a vertex or hinge end moved, a hinge
// dropped or re-attached). Whatever validate_scaffold accepts goes through check_validity with a
// modest sample count, so one input runs in well under a second. Nothing may crash, leak, hit
// undefined behaviour or throw.
#include <algorithm>
#include <fuzzer/FuzzedDataProvider.h>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "popup/mechanisms/box_fold.hpp"
#include "popup/mechanisms/floating_layer.hpp"
#include "popup/mechanisms/horizontal_translation.hpp"
#include "popup/mechanisms/rotation_arm.hpp"
#include "popup/mechanisms/step_fold.hpp"
#include "popup/mechanisms/tent_fold.hpp"
#include "popup/mechanisms/v_box_fold.hpp"
#include "popup/mechanisms/v_fold.hpp"
#include "popup/model/card.hpp"
#include "popup/simulation/check_validity.hpp"

namespace {

using namespace popup;

/// A length (mm) in [lo, hi], or once in 16 a value no parameter check should let through.
double length(FuzzedDataProvider& in, double lo, double hi)
{
    if (in.ConsumeIntegralInRange<int>(0, 15) == 0) {
        static const double special[] = {std::numeric_limits<double>::quiet_NaN(),
                                         std::numeric_limits<double>::infinity(),
                                         -std::numeric_limits<double>::infinity(),
                                         0.0,
                                         -1.0,
                                         1e300,
                                         1e-300,
                                         -1e300};
        return special[in.ConsumeIntegralInRange<size_t>(0, std::size(special) - 1)];
    }
    // A host shorter than `lo` (a small nested pair) leaves an empty range: the provider aborts
    // on those, so it shrinks to the one value lo.
    return in.ConsumeFloatingPointInRange<double>(lo, std::max(lo, hi));
}

void place(FuzzedDataProvider& in, Placement1D& p, const BasePatchPair& host)
{
    p.offset = length(in, -10.0, host.length);
    p.width = length(in, 1.0, host.length);
}

Result<MechanismParts> add_mechanism(FuzzedDataProvider& in, Scaffold& s, const BasePatchPair& h,
                                     const std::string& name)
{
    const double reach = std::max({h.ground_depth, h.backdrop_depth, 10.0});
    switch (in.ConsumeIntegralInRange<int>(0, 8)) {
    case 0: {
        TentFoldParams p;
        place(in, p, h);
        p.foot = length(in, 0.5, reach);
        p.foot_backdrop = length(in, 0.5, reach);
        p.slope = length(in, 0.5, 1.5 * reach);
        return add_tent_fold(s, h, p, name);
    }
    case 1: {
        StepFoldParams p;
        place(in, p, h);
        p.run_ground = length(in, 0.5, reach);
        p.run_backdrop = length(in, 0.5, reach);
        return add_step_fold(s, h, p, name);
    }
    case 2: {
        BoxFoldParams p;
        place(in, p, h);
        p.depth_ground = length(in, 0.5, reach);
        p.depth_backdrop = length(in, 0.5, reach);
        p.height = length(in, 0.5, reach);
        p.panel_pairs = in.ConsumeIntegralInRange<int>(0, 3);
        p.front = in.ConsumeBool();
        p.back = in.ConsumeBool();
        return add_box_fold(s, h, p, name);
    }
    case 3: {
        FloatingLayerParams p;
        place(in, p, h);
        p.height = length(in, 0.5, reach);
        p.support = length(in, 0.5, reach);
        p.overhang = length(in, 0.0, reach);
        return add_floating_layer(s, h, p, name);
    }
    case 4: {
        HorizontalTranslationParams p;
        place(in, p, h);
        p.run_ground = length(in, 0.5, reach);
        p.run_backdrop = length(in, 0.5, reach);
        p.reach = length(in, 0.5, 2.0 * reach);
        return add_horizontal_translation(s, h, p, name);
    }
    case 5: {
        RotationArmParams p;
        p.offset = length(in, -10.0, h.length);
        p.spine = length(in, 0.5, reach);
        p.run = length(in, 0.5, reach);
        p.arm = length(in, 0.5, reach);
        return add_rotation_arm(s, h, p, name);
    }
    case 6:
    case 7: {
        VBoxFoldParams p;
        p.offset = length(in, -10.0, h.length);
        p.side = length(in, 0.5, h.length);
        p.height = length(in, 0.5, reach);
        p.wall_angle = length(in, 0.0, M_PI / 2);
        p.back = in.ConsumeBool();
        return in.ConsumeBool() ? add_v_box_fold(s, h, p, name)
                                : add_vertical_translation(s, h, p, name);
    }
    default: {
        VFoldParams p;
        p.offset = length(in, -10.0, h.length);
        p.run = length(in, 0.5, reach);
        p.hinge_angle = length(in, 0.0, M_PI / 2);
        p.spine = length(in, 0.5, 1.5 * reach);
        p.spine_angle = length(in, 0.0, M_PI);
        return add_v_fold(s, h, p, name);
    }
    }
}

/// Small changes a careless edit or a rounding tool could make.
void perturb(FuzzedDataProvider& in, Scaffold& s)
{
    const int count = in.ConsumeIntegralInRange<int>(0, 3);
    for (int k = 0; k < count && !s.patches.empty(); ++k) {
        const Vec3 delta(in.ConsumeFloatingPointInRange<double>(-2.0, 2.0),
                         in.ConsumeFloatingPointInRange<double>(-2.0, 2.0),
                         in.ConsumeFloatingPointInRange<double>(-2.0, 2.0));
        switch (in.ConsumeIntegralInRange<int>(0, 4)) {
        case 0: { // move one outline vertex
            Patch& p = s.patches[in.ConsumeIntegralInRange<size_t>(0, s.patches.size() - 1)];
            if (!p.outer.empty())
                p.outer[in.ConsumeIntegralInRange<size_t>(0, p.outer.size() - 1)] += delta;
            break;
        }
        case 1: // move a hinge end
            if (!s.hinges.empty())
                s.hinges[in.ConsumeIntegralInRange<size_t>(0, s.hinges.size() - 1)].to += delta;
            break;
        case 2: // drop a hinge
            if (!s.hinges.empty())
                s.hinges.erase(s.hinges.begin() +
                               in.ConsumeIntegralInRange<size_t>(0, s.hinges.size() - 1));
            break;
        case 3: // re-attach a hinge to another patch
            if (!s.hinges.empty())
                s.hinges[in.ConsumeIntegralInRange<size_t>(0, s.hinges.size() - 1)].patch_b =
                    s.patches[in.ConsumeIntegralInRange<size_t>(0, s.patches.size() - 1)].id;
            break;
        default: // repeat a vertex (the closing repeat of other tools' files)
        {
            Patch& p = s.patches[in.ConsumeIntegralInRange<size_t>(0, s.patches.size() - 1)];
            if (!p.outer.empty())
                p.outer.push_back(p.outer.front());
            break;
        }
        }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    FuzzedDataProvider in(data, size);
    CardParams card;
    card.width = in.ConsumeFloatingPointInRange<double>(40.0, 300.0);
    card.depth = in.ConsumeFloatingPointInRange<double>(30.0, 200.0);
    card.paper_thickness = in.ConsumeFloatingPointInRange<double>(0.0, 1.0);
    Result<Scaffold> made = make_card(card);
    if (!made.ok)
        return 0;
    Scaffold s = std::move(made.value);
    std::vector<BasePatchPair> hosts = {central_fold(s)};
    const int mechanisms = in.ConsumeIntegralInRange<int>(1, 3);
    for (int m = 0; m < mechanisms; ++m) {
        const BasePatchPair host = hosts[in.ConsumeIntegralInRange<size_t>(0, hosts.size() - 1)];
        const Result<MechanismParts> parts = add_mechanism(in, s, host, "M" + std::to_string(m));
        if (parts.ok)
            hosts.insert(hosts.end(), parts.value.offered.begin(), parts.value.offered.end());
        else if (parts.diagnostics.empty()) {
            std::fprintf(stderr, "check_validity_fuzzer: a generator failed without a reason\n");
            std::abort();
        }
    }
    perturb(in, s);

    Result<Scaffold> valid = validate_scaffold(std::move(s));
    if (!valid.ok)
        return 0;
    ValidityOptions options;
    options.samples = in.ConsumeIntegralInRange<int>(2, 19);
    options.clearance = in.ConsumeFloatingPointInRange<double>(0.0, 1.0);
    options.refine_depth = in.ConsumeIntegralInRange<int>(0, 4);
    if (std::getenv("POPUP_FUZZ_VERBOSE"))
        std::fprintf(stderr, "%zu patches, %zu hinges, samples %d, refine %d\n",
                     valid.value.patches.size(), valid.value.hinges.size(), options.samples,
                     options.refine_depth);
    const auto t0 = std::chrono::steady_clock::now();
    const ValidityReport report = check_validity(valid.value, options);
    if (std::getenv("POPUP_FUZZ_VERBOSE"))
        std::fprintf(
            stderr, "check_validity: %.0f ms, %s\n",
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count(),
            report.valid() ? "VALID" : "INVALID");
    if (report.valid() && has_errors(report.diagnostics)) {
        std::fprintf(stderr, "check_validity_fuzzer: VALID with errors\n");
        std::abort();
    }
    return 0;
}
