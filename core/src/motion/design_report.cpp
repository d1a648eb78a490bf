#include "design_report.hpp"

#include <cmath>
#include <sstream>

#include "design_reasons.hpp"
#include "reach_floor.hpp"

namespace popup::motion {

namespace {

// A moving chain left still by the search: when its own mechanism collides with the final
// design, the report names the mechanism it would hit (the search's own choice otherwise).
std::string own_conflict(const MotionDesign& design, int j, int own_slot)
{
    const AnnealProblem& p = design.problem;
    const std::vector<MotionKind>& mapped = design.mapped;
    const AnnealState& state = design.state;
    if (mapped[j] == MotionKind::stationary)
        return {};
    const Candidate& own = p.candidates[j][int(mapped[j])];
    if (!std::isfinite(own.error_mm))
        return {};
    Slot mine;
    mine.mechanism = own.mechanism;
    mine.chains = {j};
    const CollisionVolume v = slot_volume(p, mine);
    int other = -1;
    double deepest = 0;
    for (int k = 0; k < int(state.slots.size()); ++k) {
        if (k == own_slot)
            continue;
        const double d = collision_depth(v, slot_volume(p, state.slots[k]));
        if (d > deepest) {
            deepest = d;
            other = k;
        }
    }
    if (other < 0)
        return {};
    std::ostringstream why;
    why << "its own " << to_string(mapped[j]) << " mechanism (" << own.error_mm
        << " mm from its path) collides with the one carrying "
        << chain_names(p, state.slots[other]) << " (volumes overlap by " << deepest
        << " mm) and they move too differently to share a patch (motions "
        << motion_distance(p.chains[j], p.chains[state.slots[other].chains.front()])
        << " mm apart, RMS)";
    return why.str();
}

// The best one mechanism does on chain j alone, collisions ignored: its own candidates (fitted
// to its path in map_chains) and its part printed on the page.
void set_bound(const AnnealProblem& p, int j, const ChainTarget& c, ChainReport& cr)
{
    Slot printed;
    printed.printed = true;
    printed.chains = {j};
    cr.bound_mm = carried_error(printed, c);
    cr.bound_mechanism = "printed";
    for (const Candidate& candidate : p.candidates[j])
        if (std::isfinite(candidate.error_mm) && candidate.error_mm < cr.bound_mm) {
            cr.bound_mm = candidate.error_mm;
            cr.bound_mechanism = to_string(candidate.mechanism.kind());
        }
    cr.bound = cr.bound_mm / p.diagonal;
}

// Why a chain the maker did not choose (MotionOptions::animate_only) stands where it does.
std::string unchosen_reason(const ChainReport& cr, bool printed)
{
    const std::string where = printed                 ? "its part is printed on the page"
                              : cr.status == "merged" ? cr.reason
                                                      : "a floating layer carries it";
    return "held still: the maker did not choose it to animate (animate_only); " + where;
}

} // namespace

void report_design(const MotionDesign& design, MotionResult& r)
{
    const AnnealProblem& p = design.problem;
    const std::vector<MotionKind>& mapped = design.mapped;
    const AnnealState& state = design.state;
    const std::vector<ChainTarget>& full_chains = design.full_chains;
    const std::map<int, std::string>& reasons = design.reasons;
    const std::vector<std::vector<std::string>>& slot_mechanisms = design.slot_mechanisms;
    auto conflict = [&](int j, int own_slot) { return own_conflict(design, j, own_slot); };
    auto generic = [&](int j) {
        return !reasons.count(j) || reasons.at(j).rfind("the search", 0) == 0;
    };

    // Report (eq 6.6 per chain, the vertex-weighted total, mapping and status).
    r.cost = state_cost(p, state);
    std::vector<int> slot_of(p.chains.size(), -1);
    for (int i = 0; i < int(state.slots.size()); ++i)
        for (int j : state.slots[i].chains)
            slot_of[j] = i;
    for (int j = 0; j < int(p.chains.size()); ++j) {
        const ChainTarget& c = full_chains[j];
        ChainReport cr;
        cr.name = c.name;
        cr.weight = c.weight;
        cr.s = c.s;
        cr.target = c.target;
        const int i = slot_of[j];
        if (i >= 0) {
            const Slot& s = state.slots[i];
            cr.mapping = to_string(s.mechanism.kind());
            if (i < int(slot_mechanisms.size()))
                cr.mechanisms = slot_mechanisms[i];
            cr.achieved = carried_path(s, c);
            cr.error_mm = carried_error(s, c);
            if (s.chains.size() > 1) {
                cr.status = "merged";
                std::string others;
                for (int k : s.chains)
                    if (k != j)
                        others += (others.empty() ? "" : ", ") + p.chains[k].name;
                std::ostringstream why;
                why << "shares its " << cr.mapping << " mechanism with " << others
                    << " (they move alike: their motions, less their open-state places, within "
                    << p.alike_fraction * p.diagonal << " mm RMS; each part keeps its place on the "
                    << "patch)";
                cr.reason = why.str();
            } else if (s.mechanism.kind() == MotionKind::stationary) {
                cr.status = "stationary";
                const std::string hit = generic(j) ? conflict(j, i) : std::string();
                cr.reason = !hit.empty()       ? hit + "; a floating layer carries it"
                            : reasons.count(j) ? reasons.at(j)
                            : mapped[j] == MotionKind::stationary
                                ? "it does not move (a floating layer carries it)"
                                : "the search found the floating layer cheaper than moving it";
            } else {
                cr.status = "animated";
            }
        } else {
            // Printed on the page: it moves with the ground page's point under it.
            cr.mapping = "stationary";
            cr.status = "stationary";
            const std::string hit = generic(j) ? conflict(j, -1) : std::string();
            cr.reason = !hit.empty()       ? hit + "; its part is printed on the page"
                        : reasons.count(j) ? reasons.at(j)
                                           : "no mechanism carries it";
            Slot printed;
            printed.printed = true;
            printed.chains = {j};
            cr.achieved = carried_path(printed, c);
            cr.error_mm = carried_error(printed, c);
        }
        if (j < int(design.unchosen.size()) && design.unchosen[j])
            cr.reason = unchosen_reason(cr, i < 0);
        cr.error = cr.error_mm / p.diagonal;
        r.weighted_error += c.weight * cr.error;
        cr.floor_mm = reach_floor_mm(c, p.card);
        cr.floor = cr.floor_mm / p.diagonal;
        r.weighted_floor += c.weight * cr.floor;
        set_bound(p, j, c, cr);
        r.weighted_bound += c.weight * cr.bound;
        r.chains.push_back(cr);
    }
    if (!r.valid)
        r.diagnostics.push_back(
            Diagnostic::warning(DiagnosticCode::no_design_found,
                                "the design does not pass the full simulator's validity check"));
}

} // namespace popup::motion
