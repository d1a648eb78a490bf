#include "popup/fitting/design_repair.hpp"

#include "design_trial.hpp"
#include "mechanism_repairs.hpp"
#include "plan_edits.hpp"

namespace popup {
namespace {

// Each repair tried is a rebuild and, unless a generator refuses it, a full validity check
// (~0.1 s on a few mechanisms): at most this many per design, then culprits are dropped.
constexpr int max_repair_tries = 16;

/// Per plan, the last repair done to it; a drop also warns.
struct RepairLog {
    std::vector<FitRepair> last;
    Diagnostics warnings;

    void repaired(const std::vector<MechanismPlan>& before, size_t i, const RepairAttempt& a,
                  const std::string& why)
    {
        last[i] = {before[i].name, a.action, a.change + ", because " + why};
        for (int k : a.carried) {
            const MechanismPlan& p = before[size_t(k)];
            const std::string changes = describe_changes(p, a.plans[size_t(k)]);
            last[size_t(k)] = {p.name, a.action,
                               a.action + " with " + before[i].name + ", which it stands on" +
                                   (changes.empty() ? "" : " (" + changes + ")")};
        }
    }

    void dropped(const MechanismPlan& p, size_t i, const std::string& reason)
    {
        last[i] = {p.name, "dropped", reason};
        const std::string msg =
            p.name + " (" + catalogue_entry(p.kind).name + ") dropped: " + reason;
        warnings.push_back(
            Diagnostic::warning(DiagnosticCode::mechanism_dropped, msg, about_parameter(p.name)));
    }
};

std::string drop_reason(const DesignTrial& t, const std::vector<RepairAttempt>& tried,
                        bool out_of_tries)
{
    if (out_of_tries)
        return t.why + "; no repair tried (all " + std::to_string(max_repair_tries) +
               " tries of this design were spent)";
    if (tried.empty())
        return t.why + (t.failure == TrialFailure::host_missing
                            ? ", and no other pair at its place takes it"
                            : "; it could not be shrunk (its parts would fall below the "
                              "smallest part), trimmed or moved to make it fit");
    std::string what;
    for (size_t k = 0; k < tried.size(); ++k)
        what += (k == 0 ? "" : k + 1 == tried.size() ? " and " : ", ") + tried[k].what;
    return t.why + "; " + what + " did not help";
}

} // namespace

RepairOutcome build_until_valid(const CardParams& card, std::vector<MechanismPlan> plans,
                                double min_part, const CancelFlag* cancel)
{
    const RepairLimits limits{min_part, 1e-6 * std::max(card.width, card.depth)};
    std::vector<bool> keep(plans.size(), true);
    RepairLog log{std::vector<FitRepair>(plans.size()), {}};
    std::map<std::string, BasePatchPair> seen; // every pair any trial built
    int tries_left = max_repair_tries;
    DesignTrial trial = try_design(card, plans, keep, cancel);
    while (trial.failure != TrialFailure::none) {
        for (const auto& [name, pair] : trial.built.pairs)
            seen[name] = pair;
        const size_t i = size_t(trial.culprit);
        const std::vector<RepairAttempt> attempts =
            tries_left > 0 ? repair_attempts(plans, trial, seen, limits)
                           : std::vector<RepairAttempt>{};
        std::vector<RepairAttempt> tried;
        bool repaired = false;
        for (const RepairAttempt& a : attempts) {
            if (tries_left-- <= 0)
                break;
            DesignTrial next = try_design(card, a.plans, keep, cancel);
            tried.push_back(a);
            if (!next.implicated[i]) {
                log.repaired(plans, i, a, trial.why);
                plans = a.plans;
                trial = std::move(next);
                repaired = true;
                break;
            }
        }
        if (repaired)
            continue;
        keep[i] = false;
        log.dropped(plans[i], i, drop_reason(trial, tried, attempts.empty() && tries_left <= 0));
        trial = try_design(card, plans, keep, cancel);
    }
    RepairOutcome out;
    out.scaffold = trial.built.scaffold;
    out.pairs = trial.built.pairs;
    out.kept.assign(plans.size(), false);
    bool any = false;
    for (size_t i = 0; i < plans.size(); ++i) {
        out.kept[i] = keep[i] && !trial.built.parts[i].name.empty();
        any |= out.kept[i];
        if (!log.last[i].action.empty())
            out.repairs.push_back(log.last[i]);
    }
    out.warnings = log.warnings;
    out.report = trial.report;
    out.valid = any && trial.report.valid();
    out.plans = std::move(plans);
    return out;
}

} // namespace popup
