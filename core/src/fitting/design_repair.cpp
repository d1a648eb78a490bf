#include "popup/fitting/design_repair.hpp"

#include <algorithm>
#include <map>

namespace popup {
namespace {

/// The scaffold of some plans: card first, then each plan on the pair its host offered.
struct Built {
    Scaffold scaffold;
    std::vector<MechanismParts> parts; ///< per plan; empty name when not built
    std::vector<std::string> refused;  ///< per plan: why the generator refused it, or empty
    std::map<std::string, BasePatchPair> pairs; ///< offered by the card and the built plans
};

Built build(const CardParams& card, const std::vector<MechanismPlan>& plans,
            const std::vector<bool>& keep)
{
    Built b;
    auto made = make_card(card);
    b.scaffold = made.value;
    b.parts.resize(plans.size());
    b.refused.resize(plans.size());
    std::map<std::string, BasePatchPair> pairs{{"central fold", central_fold(b.scaffold)}};
    for (size_t i = 0; i < plans.size(); ++i) {
        if (!keep[i])
            continue;
        const MechanismPlan& p = plans[i];
        const auto host = pairs.find(p.host);
        if (host == pairs.end()) {
            b.refused[i] = "its host " + p.host + " is not in the design";
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
            pairs[offered.name] = offered;
        b.parts[i] = added.value;
    }
    b.pairs = pairs;
    return b;
}

/// The plan a patch belongs to, or -1 for the card.
int owner_of(const Built& b, int patch)
{
    for (size_t i = 0; i < b.parts.size(); ++i)
        for (int id : b.parts[i].patches)
            if (id == patch)
                return int(i);
    return -1;
}

} // namespace

RepairOutcome build_until_valid(const CardParams& card, const std::vector<MechanismPlan>& plans,
                                const CancelFlag* cancel)
{
    RepairOutcome out;
    std::vector<bool> keep(plans.size(), true);
    auto drop = [&](size_t i, const std::string& why) {
        // What stands on it goes with it.
        std::vector<size_t> gone{i};
        keep[i] = false;
        for (size_t k = i + 1; k < plans.size(); ++k)
            if (plans[k].parent >= 0 && !keep[size_t(plans[k].parent)] && keep[k]) {
                keep[k] = false;
                gone.push_back(k);
            }
        for (size_t k : gone) {
            const std::string reason =
                k == i ? why : "it stood on " + plans[i].name + ", which was dropped";
            out.repairs.push_back({plans[k].name, "dropped", reason});
            const std::string msg =
                plans[k].name + " (" + catalogue_entry(plans[k].kind).name + ") dropped: " + reason;
            out.warnings.push_back(Diagnostic::warning(DiagnosticCode::mechanism_dropped, msg,
                                                       about_parameter(plans[k].name)));
        }
    };
    Built built;
    ValidityReport report;
    ValidityOptions vo;
    vo.cancel = cancel;
    for (;;) {
        built = build(card, plans, keep);
        bool refused = false;
        for (size_t i = 0; i < plans.size(); ++i)
            if (keep[i] && !built.refused[i].empty()) {
                drop(i, built.refused[i]);
                refused = true;
                break;
            }
        if (refused)
            continue;
        std::vector<MechanismParts> present;
        for (const auto& p : built.parts)
            if (!p.name.empty())
                present.push_back(p);
        const auto conflicts = placement_conflicts(present);
        if (!conflicts.empty()) {
            for (size_t i = plans.size(); i-- > 0;)
                if (keep[i] && (plans[i].name == conflicts.front().second ||
                                plans[i].name == conflicts.front().first)) {
                    drop(i, "it sweeps into " +
                                (plans[i].name == conflicts.front().second
                                     ? conflicts.front().first
                                     : conflicts.front().second) +
                                " along their hinge when the card closes (§4.2.2)");
                    break;
                }
            continue;
        }
        if (present.empty())
            break;
        report = check_validity(built.scaffold, vo);
        if (report.valid())
            break;
        // The mechanism the findings point at, most nested first; the last one otherwise.
        int culprit = -1;
        std::string why;
        for (const Diagnostic& d : report.diagnostics) {
            if (d.severity != Severity::error)
                continue;
            for (int id : d.patches) {
                const int o = owner_of(built, id);
                if (o > culprit) {
                    culprit = o;
                    why = d.message;
                }
            }
            if (why.empty())
                why = d.message;
        }
        if (culprit < 0)
            for (size_t i = plans.size(); i-- > 0;)
                if (keep[i]) {
                    culprit = int(i);
                    break;
                }
        drop(size_t(culprit), "the validity check failed: " + why);
    }
    out.scaffold = built.scaffold;
    out.pairs = built.pairs;
    out.kept.assign(plans.size(), false);
    bool any = false;
    for (size_t i = 0; i < plans.size(); ++i) {
        out.kept[i] = keep[i] && !built.parts[i].name.empty();
        any |= out.kept[i];
    }
    out.report = report;
    out.valid = any && report.valid();
    return out;
}

} // namespace popup
