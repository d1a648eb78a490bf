#include "mechanism_repairs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "plan_edits.hpp"

namespace popup {
namespace {

// A few steps, largest first: each try costs build_until_valid a rebuild and a full validity
// check, and it caps how many it makes.
constexpr double shrink_factors[] = {0.9, 0.8, 0.7};
constexpr size_t max_rehosts = 2;

RepairAttempt attempt(PlanEdit e, const MechanismPlan& before, size_t i, std::string action,
                      std::string what)
{
    const std::string changes = describe_changes(before, e.plans[i]);
    std::string change = changes.empty() ? what : what + " (" + changes + ")";
    return {std::move(e.plans), std::move(action), std::move(what), std::move(change),
            std::move(e.carried)};
}

void add_shrinks(const std::vector<MechanismPlan>& plans, size_t i, const RepairLimits& limits,
                 std::vector<RepairAttempt>& out)
{
    for (double factor : shrink_factors)
        if (auto e = scale_about_place(plans, i, factor, limits.min_part))
            out.push_back(attempt(std::move(*e), plans[i], i, "shrunk",
                                  "shrunk to " + std::to_string(int(std::lround(factor * 100))) +
                                      " % about its middle"));
}

/// Where plan `k` sweeps, along the hinge of `onto` (mm from its origin); nothing unless built
/// on a hinge parallel to it.
std::optional<std::pair<double, double>> sweep_along(const BuiltPlans& b, size_t k,
                                                     const BasePatchPair& onto)
{
    const MechanismParts& parts = b.parts[k];
    const auto host = b.pairs.find(parts.host);
    if (parts.name.empty() || host == b.pairs.end() ||
        std::abs(std::abs(host->second.axis.dot(onto.axis)) - 1) > 1e-6)
        return std::nullopt;
    auto along = [&](double y) {
        return (host->second.to_world(0, y, 0) - onto.origin).dot(onto.axis);
    };
    const double y0 = along(parts.sweep_from), y1 = along(parts.sweep_to);
    return std::make_pair(std::min(y0, y1), std::max(y0, y1));
}

/// Plan `i` cut along its hinge clear of plan `other`'s sweep, its facing end panels off first
/// when it keeps the other end's (thesis §5.1.2: "partially trimmed").
std::optional<PlanEdit> trim_away(const std::vector<MechanismPlan>& plans, const DesignTrial& t,
                                  size_t i, const BasePatchPair& host, const RepairLimits& limits)
{
    const auto theirs = sweep_along(t.built, size_t(t.other), host);
    const auto mine = sweep_along(t.built, i, host);
    if (!theirs || !mine)
        return std::nullopt;
    std::vector<MechanismPlan> edited = plans;
    MechanismPlan& p = edited[i];
    const double a = p.offset(), b = a + p.extent();
    double lead = a - mine->first, tail = mine->second - b;
    const bool box = p.kind == MechanismKind::box_fold;
    const double inf = std::numeric_limits<double>::infinity();
    if (a + b >= theirs->first + theirs->second) { // it lies after the other: cut its front
        if (box && p.as<BoxFoldParams>().front && p.as<BoxFoldParams>().back) {
            p.as<BoxFoldParams>().front = false;
            lead = 0;
        }
        const double lo = theirs->second + limits.margin + lead;
        if (lo <= a)
            return PlanEdit{edited, {}};
        return cut_along_hinge(edited, i, lo, inf, limits.min_part, limits.margin);
    }
    if (box && p.as<BoxFoldParams>().front && p.as<BoxFoldParams>().back) {
        p.as<BoxFoldParams>().back = false;
        tail = 0;
    }
    const double hi = theirs->first - limits.margin - tail;
    if (hi >= b)
        return PlanEdit{edited, {}};
    return cut_along_hinge(edited, i, -inf, hi, limits.min_part, limits.margin);
}

std::optional<RepairAttempt> trim(const std::vector<MechanismPlan>& plans, const DesignTrial& t,
                                  const RepairLimits& limits)
{
    const size_t i = size_t(t.culprit);
    const MechanismPlan& p = plans[i];
    const auto host = t.built.pairs.find(p.host);
    if (!catalogue_entry(p.kind).field("width") || host == t.built.pairs.end())
        return std::nullopt;
    const double a = p.offset(), b = a + p.extent(), length = host->second.length;
    if (t.failure == TrialFailure::refused && (a < 0 || b > length)) {
        auto e = cut_along_hinge(plans, i, limits.margin, length - limits.margin, limits.min_part,
                                 limits.margin);
        if (!e)
            return std::nullopt;
        return attempt(std::move(*e), p, i, "trimmed", "trimmed to the length of " + p.host);
    }
    if (t.other < 0 || t.failure == TrialFailure::refused)
        return std::nullopt;
    auto e = trim_away(plans, t, i, host->second, limits);
    if (!e || describe_changes(p, e->plans[i]).empty()) // clear of it already: no trim helps
        return std::nullopt;
    const std::string other = plans[size_t(t.other)].name;
    const bool cut = std::abs(e->plans[i].extent() - p.extent()) > 0;
    return attempt(std::move(*e), p, i, "trimmed",
                   cut ? "trimmed along its hinge away from " + other
                       : "its end panels facing " + other + " taken off");
}

/// The plan offering pair `name`, -1 for the card's central fold, -2 for none.
int offered_by(const std::vector<MechanismPlan>& plans, const std::string& name)
{
    if (name == "central fold")
        return -1;
    const std::string owner = name.substr(0, name.find('.'));
    for (size_t k = 0; k < plans.size(); ++k)
        if (plans[k].name == owner)
            return int(k);
    return -2;
}

void add_rehosts(const std::vector<MechanismPlan>& plans, const DesignTrial& t,
                 const std::map<std::string, BasePatchPair>& seen, const RepairLimits& limits,
                 std::vector<RepairAttempt>& out)
{
    const size_t i = size_t(t.culprit);
    const MechanismPlan& p = plans[i];
    const auto from = seen.find(p.host);
    if (from == seen.end())
        return;
    // Where its host stood first, then the page, then the other pairs by name.
    std::vector<std::string> names;
    if (p.parent >= 0)
        names.push_back(plans[size_t(p.parent)].host);
    names.push_back("central fold");
    for (const auto& [name, pair] : t.built.pairs)
        names.push_back(name);
    std::vector<std::string> tried;
    size_t added = 0;
    for (const std::string& name : names) {
        const auto to = t.built.pairs.find(name);
        const int parent = offered_by(plans, name);
        if (name == p.host || to == t.built.pairs.end() || parent < -1 || parent >= int(i) ||
            std::count(tried.begin(), tried.end(), name))
            continue;
        tried.push_back(name);
        auto e = move_to_pair(plans, i, from->second, to->second, parent, limits.margin);
        if (!e)
            continue;
        const std::string onto = name == "central fold" ? "the central fold" : name;
        out.push_back(attempt(std::move(*e), p, i, "re-hosted",
                              "moved from " + p.host + " onto " + onto +
                                  " at the same place along the hinge"));
        if (++added == max_rehosts)
            return;
    }
}

} // namespace

std::vector<RepairAttempt> repair_attempts(const std::vector<MechanismPlan>& plans,
                                           const DesignTrial& trial,
                                           const std::map<std::string, BasePatchPair>& seen,
                                           const RepairLimits& limits)
{
    std::vector<RepairAttempt> out;
    const size_t i = size_t(trial.culprit);
    if (trial.failure != TrialFailure::host_missing) {
        add_shrinks(plans, i, limits, out);
        if (auto t = trim(plans, trial, limits))
            out.push_back(std::move(*t));
    }
    add_rehosts(plans, trial, seen, limits, out);
    return out;
}

} // namespace popup
