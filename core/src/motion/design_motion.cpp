#include "popup/motion/design_motion.hpp"

#include <chrono>

#include "design_from_targets.hpp"

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
