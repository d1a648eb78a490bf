#include "design_from_targets.hpp"

#include <string>

#include "build_design.hpp"
#include "collision_repair.hpp"
#include "design_report.hpp"
#include "design_search.hpp"
#include "greedy_finish.hpp"
#include "map_chains.hpp"
#include "start_layout.hpp"

namespace popup::motion {

namespace {

// Every name of options.animate_only is a chain's: else one error naming the others and listing
// the chains found.
void check_animate_only(Diagnostics& out, const MotionTargets& targets, const MotionOptions& o)
{
    std::string found, unknown;
    for (const LinkageChain& chain : targets.chains)
        found += (found.empty() ? "" : ", ") + chain.name;
    for (const std::string& name : o.animate_only) {
        bool known = false;
        for (const LinkageChain& chain : targets.chains)
            known = known || chain.name == name;
        if (!known)
            unknown += (unknown.empty() ? "\"" : ", \"") + name + "\"";
    }
    if (!unknown.empty())
        out.push_back(
            Diagnostic::error(DiagnosticCode::bad_option,
                              "MotionOptions.animate_only: no chain is named " + unknown +
                                  "; the chains found: " + (found.empty() ? "none" : found),
                              about_parameter("animate_only")));
}

// The options (check_motion_options) and the targets the stages rely on, each bad one with the
// option it names.
Diagnostics check_inputs(const MotionTargets& targets, const MotionOptions& o)
{
    Diagnostics out = check_motion_options(o);
    auto bad = [&](const std::string& option, const std::string& message) {
        out.push_back(
            Diagnostic::error(DiagnosticCode::bad_option, message, about_parameter(option)));
    };
    if (targets.paths.size() != targets.chains.size())
        bad("targets", "the targets have " + std::to_string(targets.paths.size()) + " paths for " +
                           std::to_string(targets.chains.size()) + " chains; they must match");
    if (!(targets.diagonal_mm > 0))
        bad("targets", "the character's diagonal on the card (" +
                           std::to_string(targets.diagonal_mm) + " mm) must be > 0");
    for (std::size_t j = 0; j < targets.paths.size(); ++j) {
        const ChainPath& path = targets.paths[j];
        if (path.s.size() < 2 || path.effector.size() != path.s.size())
            bad("targets", "chain " + targets.chains[j].name + ": its path has " +
                               std::to_string(path.s.size()) + " samples and " +
                               std::to_string(path.effector.size()) +
                               " effector points; it needs >= 2 of each, as many");
    }
    check_animate_only(out, targets, o);
    return out;
}

} // namespace

Result<MotionResult> design_from_targets(const MotionTargets& targets, const MotionOptions& o,
                                         const CancelFlag* cancel, std::atomic<double>* progress)
{
    Result<MotionResult> out;
    MotionResult& r = out.value;
    r.targets = targets;
    const Clock::time_point begun = Clock::now();
    const Diagnostics bad = check_inputs(targets, o);
    if (!bad.empty()) {
        out.fail_with(bad);
        return out;
    }
    r.card = o.view.card;

    // Mapping and parameter estimation (thesis §6.2–6.3), then the search's start (§6.4).
    Clock::time_point t = Clock::now();
    MotionDesign design = map_chains(targets, o, r.card, cancel, progress);
    r.timings.add("mapping", seconds_since(t));
    start_layout(design);

    // Simulated annealing: independent search chains on their own threads, best kept.
    t = Clock::now();
    r.iterations = search_design(design, o, cancel, progress);
    r.timings.add("annealing", seconds_since(t));

    // Compound moves the search rarely makes, then what it left unresolved.
    greedy_finish(design);
    release_far_remaps(design);
    t = Clock::now();
    repair_collisions(design);
    r.timings.add("collision repair", seconds_since(t));

    // The library's generators and the full simulator; what they refuse is made stationary.
    t = Clock::now();
    const Result<double> built = build_design(design, r, cancel);
    if (!built.ok) {
        out.fail_with(built.diagnostics);
        return out;
    }
    out.diagnostics.insert(out.diagnostics.end(), built.diagnostics.begin(),
                           built.diagnostics.end());
    r.timings.add("build", seconds_since(t) - built.value);
    r.timings.add("validity", built.value);

    report_design(design, r);
    r.timings.total_s = seconds_since(begun);
    if (progress)
        progress->store(1.0);
    out.diagnostics.insert(out.diagnostics.end(), r.diagnostics.begin(), r.diagnostics.end());
    return out;
}

} // namespace popup::motion
