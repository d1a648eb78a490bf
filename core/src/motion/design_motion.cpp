#include "popup/motion/design_motion.hpp"

#include <algorithm>
#include <chrono>

#include "design_from_targets.hpp"
#include "motion_outlines.hpp"

namespace popup {

Result<MotionResult> design_motion(const Animation& animation, const MotionOptions& options,
                                   const CancelFlag* cancel, std::atomic<double>* progress)
{
    const auto start = std::chrono::steady_clock::now();
    Result<MotionTargets> targets = motion_targets(animation, options.view, options.chains);
    if (!targets.ok) {
        Result<MotionResult> out;
        out.fail_with(targets.diagnostics);
        return out;
    }
    const double input_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stop_if_cancelled(cancel, "design_motion: targets");
    Result<MotionResult> out =
        motion::design_from_targets(targets.value, options, cancel, progress);
    // Patches: the body parts' outlines on the built design (needs the mesh, so here).
    if (out.ok && options.outlines) {
        const auto t = std::chrono::steady_clock::now();
        const std::size_t before = out.value.diagnostics.size();
        motion::outline_motion(animation, out.value, cancel);
        out.diagnostics.insert(out.diagnostics.end(), out.value.diagnostics.begin() + long(before),
                               out.value.diagnostics.end());
        const double outline_s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
        auto& timings = out.value.timings_s;
        auto total = std::find_if(timings.begin(), timings.end(),
                                  [](const auto& x) { return x.first == "total"; });
        if (total != timings.end()) {
            total->second += outline_s;
            timings.insert(total, {"outlines", outline_s});
        } else {
            timings.push_back({"outlines", outline_s});
        }
    }
    // The input stage first; the total counts it too.
    out.value.timings_s.insert(out.value.timings_s.begin(), {"targets", input_s});
    for (auto& [stage, seconds] : out.value.timings_s)
        if (stage == "total")
            seconds += input_s;
    out.diagnostics.insert(out.diagnostics.begin(), targets.diagnostics.begin(),
                           targets.diagnostics.end());
    return out;
}

} // namespace popup
