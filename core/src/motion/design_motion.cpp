#include "popup/motion/design_motion.hpp"

#include "design_from_targets.hpp"
#include "design_types.hpp"
#include "motion_outlines.hpp"

namespace popup {

using motion::Clock;
using motion::seconds_since;

Result<MotionResult> design_motion(const Animation& animation, const MotionOptions& options,
                                   const CancelFlag* cancel, std::atomic<double>* progress)
{
    const Clock::time_point start = Clock::now();
    Result<MotionResult> out;
    if (const Diagnostics bad = check_motion_options(options); !bad.empty()) {
        out.fail_with(bad);
        return out;
    }
    Result<MotionTargets> targets = motion_targets(animation, options.view, options.chains);
    if (!targets.ok) {
        out.fail_with(targets.diagnostics);
        return out;
    }
    const double input_s = seconds_since(start);
    stop_if_cancelled(cancel, "design_motion: targets");
    out = motion::design_from_targets(targets.value, options, cancel, progress);
    StageTimings& timings = out.value.timings;
    // Patches: the body parts' outlines on the built design (needs the mesh, so here).
    if (out.ok && options.outlines) {
        const Clock::time_point t = Clock::now();
        const std::size_t before = out.value.diagnostics.size();
        motion::outline_motion(animation, out.value, cancel);
        out.diagnostics.insert(out.diagnostics.end(), out.value.diagnostics.begin() + long(before),
                               out.value.diagnostics.end());
        timings.add("outlines", seconds_since(t));
    }
    // The input stage first; the total counts it and the outlines too.
    timings.stages.insert(timings.stages.begin(), {"targets", input_s});
    timings.total_s = seconds_since(start);
    out.diagnostics.insert(out.diagnostics.begin(), targets.diagnostics.begin(),
                           targets.diagnostics.end());
    return out;
}

} // namespace popup
