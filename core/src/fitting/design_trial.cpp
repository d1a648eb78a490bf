#include "design_trial.hpp"

#include <algorithm>

namespace popup {

BuiltPlans build_plans(const CardParams& card, const std::vector<MechanismPlan>& plans,
                       const std::vector<bool>& keep)
{
    BuiltPlans b;
    b.scaffold = make_card(card).value;
    b.parts.resize(plans.size());
    b.refused.resize(plans.size());
    b.host_missing.assign(plans.size(), false);
    b.pairs = {{"central fold", central_fold(b.scaffold)}};
    for (size_t i = 0; i < plans.size(); ++i) {
        if (!keep[i])
            continue;
        const MechanismPlan& p = plans[i];
        const auto host = b.pairs.find(p.host);
        if (host == b.pairs.end()) {
            b.refused[i] = "its host " + p.host + " is not in the design";
            b.host_missing[i] = true;
            continue;
        }
        // Round-off between the fitted host and the built one must not push a mechanism that
        // spans its whole host off its end.
        DesignedMechanism q = p;
        const double length = host->second.length;
        q.set_value("offset", std::clamp(q.offset(), 0.0, length));
        if (catalogue_entry(q.kind).field("width")) {
            const double width = q.value("width");
            if (q.offset() + width > length && q.offset() + width < length * 1.01) {
                q.set_value("offset", std::max(0.0, length - width));
                q.set_value("width", std::min(width, length - q.offset()));
            }
        }
        const Result<MechanismParts> added = add_mechanism(b.scaffold, host->second, q);
        if (!added.ok) {
            b.refused[i] = added.diagnostics.empty() ? "its generator refused it"
                                                     : added.diagnostics.front().message;
            continue;
        }
        for (const BasePatchPair& offered : added.value.offered)
            b.pairs[offered.name] = offered;
        b.parts[i] = added.value;
    }
    return b;
}

namespace {

/// The plan a patch belongs to, or -1 for the card.
int owner_of(const BuiltPlans& b, int patch)
{
    for (size_t i = 0; i < b.parts.size(); ++i)
        for (int id : b.parts[i].patches)
            if (id == patch)
                return int(i);
    return -1;
}

int plan_named(const std::vector<MechanismPlan>& plans, const std::vector<bool>& keep,
               const std::string& name)
{
    for (size_t i = 0; i < plans.size(); ++i)
        if (keep[i] && plans[i].name == name)
            return int(i);
    return -1;
}

/// The first plan the generators refused, or false.
bool find_refusal(DesignTrial& t, const std::vector<MechanismPlan>& plans,
                  const std::vector<bool>& keep)
{
    for (size_t i = 0; i < keep.size(); ++i)
        t.implicated[i] = keep[i] && !t.built.refused[i].empty();
    for (size_t i = 0; i < keep.size(); ++i)
        if (t.implicated[i]) {
            t.failure =
                t.built.host_missing[i] ? TrialFailure::host_missing : TrialFailure::refused;
            t.culprit = int(i);
            t.why = t.built.refused[i];
            if (t.built.host_missing[i]) // a host goes missing when what offers it is dropped
                t.why = "it stood on " + plans[i].host.substr(0, plans[i].host.find('.')) +
                        ", which was dropped";
            return true;
        }
    return false;
}

/// The later of the first two plans sweeping into each other along their hinge, or false.
bool find_sweep_conflict(DesignTrial& t, const std::vector<MechanismPlan>& plans,
                         const std::vector<bool>& keep)
{
    std::vector<MechanismParts> present;
    for (const auto& p : t.built.parts)
        if (!p.name.empty())
            present.push_back(p);
    const auto conflicts = placement_conflicts(present);
    for (const auto& [a, b] : conflicts) {
        t.implicated[size_t(plan_named(plans, keep, a))] = true;
        t.implicated[size_t(plan_named(plans, keep, b))] = true;
    }
    if (conflicts.empty())
        return false;
    const int a = plan_named(plans, keep, conflicts.front().first);
    const int b = plan_named(plans, keep, conflicts.front().second);
    t.failure = TrialFailure::swept_into;
    t.culprit = std::max(a, b);
    t.other = std::min(a, b);
    t.why = "it sweeps into " + plans[size_t(t.other)].name +
            " along their hinge when the card closes (§4.2.2)";
    return true;
}

/// The plan the failed check's errors point at, most nested first; the last built otherwise.
void find_invalid(DesignTrial& t, const std::vector<bool>& keep)
{
    t.failure = TrialFailure::invalid;
    std::string message;
    for (const Diagnostic& d : t.report.diagnostics) {
        if (d.severity != Severity::error)
            continue;
        std::vector<int> owners;
        for (int id : d.patches) {
            const int o = owner_of(t.built, id);
            if (o >= 0)
                t.implicated[size_t(o)] = true;
            owners.push_back(o);
        }
        const int most_nested =
            owners.empty() ? -1 : *std::max_element(owners.begin(), owners.end());
        if (most_nested > t.culprit) {
            t.culprit = most_nested;
            message = d.message;
            t.other = -1;
            for (int o : owners)
                if (o >= 0 && o != most_nested)
                    t.other = o;
        }
        if (message.empty())
            message = d.message;
    }
    if (t.culprit < 0)
        for (size_t i = keep.size(); i-- > 0;)
            if (keep[i] && !t.built.parts[i].name.empty()) {
                t.culprit = int(i);
                t.implicated[i] = true;
                break;
            }
    t.why = "the validity check failed: " + message;
}

} // namespace

DesignTrial try_design(const CardParams& card, const std::vector<MechanismPlan>& plans,
                       const std::vector<bool>& keep, const CancelFlag* cancel)
{
    DesignTrial t;
    t.built = build_plans(card, plans, keep);
    t.implicated.assign(plans.size(), false);
    if (find_refusal(t, plans, keep) || find_sweep_conflict(t, plans, keep))
        return t;
    const bool any = std::any_of(t.built.parts.begin(), t.built.parts.end(),
                                 [](const MechanismParts& p) { return !p.name.empty(); });
    if (!any)
        return t;
    ValidityOptions vo;
    vo.cancel = cancel;
    t.report = check_validity(t.built.scaffold, vo);
    t.checked = true;
    if (!t.report.valid())
        find_invalid(t, keep);
    return t;
}

} // namespace popup
