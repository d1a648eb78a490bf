#include "build_design.hpp"

#include <set>

#include "build_mechanism.hpp"
#include "design_reasons.hpp"
#include "give_way.hpp"
#include "popup/model/card.hpp"
#include "popup/simulation/check_validity.hpp"

namespace popup::motion {

namespace {

std::string mechanism_name(MotionKind kind, const std::string& chain)
{
    static const char* prefix[] = {"VerticalTranslation", "DiagonalTranslation",
                                   "HorizontalTranslation", "RotationArm", "FloatingLayer"};
    std::string clean;
    for (char c : chain)
        clean += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    return std::string(prefix[int(kind)]) + "_" + clean;
}

} // namespace

Result<double> build_design(MotionDesign& d, MotionResult& r, const CancelFlag* cancel)
{
    Result<double> out;
    const AnnealProblem& p = d.problem;
    AnnealState& state = d.state;
    std::map<int, std::string>& reasons = d.reasons;
    double validity_s = 0;
    std::vector<std::vector<std::string>>& slot_mechanisms = d.slot_mechanisms;
    for (int round = 0;; ++round) {
        stop_if_cancelled(cancel, "design_motion: building");
        Result<Scaffold> card = make_card(r.card);
        if (!card.ok) {
            out.fail_with(card.diagnostics);
            return out;
        }
        Scaffold scaffold = card.value;
        const BasePatchPair host = central_fold(scaffold);
        std::vector<FittedMechanism> rows;
        std::vector<std::set<int>> slot_patches;
        slot_mechanisms.clear();
        int refused = -1;
        std::string refusal;
        for (int i = 0; i < int(state.slots.size()); ++i) {
            const Slot& s = state.slots[i];
            const std::string name =
                mechanism_name(s.mechanism.kind(), p.chains[s.chains.front()].name);
            Result<std::vector<MechanismParts>> built =
                build_mechanism(scaffold, host, s.mechanism, name, rows);
            if (!built.ok) {
                refused = i;
                refusal = built.diagnostics.empty() ? "refused" : built.diagnostics[0].message;
                break;
            }
            std::set<int> ids;
            std::vector<std::string> names;
            for (const MechanismParts& part : built.value) {
                ids.insert(part.patches.begin(), part.patches.end());
                names.push_back(part.name);
            }
            slot_patches.push_back(ids);
            slot_mechanisms.push_back(names);
        }
        if (refused >= 0) {
            out.warn(DiagnosticCode::mechanism_dropped,
                     "chain " + chain_names(p, state.slots[refused]) +
                         ": the generator refused its mechanism: " + refusal);
            demote(p, state, refused, "the generator refused its mechanism: " + refusal, reasons);
            continue;
        }
        const Clock::time_point v0 = Clock::now();
        ValidityOptions vo;
        vo.cancel = cancel;
        vo.clearance = 0.0;
        const ValidityReport report = check_validity(scaffold, vo);
        validity_s += seconds_since(v0);
        r.scaffold = scaffold;
        r.mechanisms = rows;
        r.valid = report.valid();
        if (r.valid || state.slots.empty() || round >= 2 * int(p.chains.size()) + 2) {
            if (!r.valid)
                for (const Diagnostic& d : report.diagnostics)
                    r.diagnostics.push_back(d);
            break;
        }
        // The lightest mechanism among the crossing patches (or, for another verdict, the
        // lightest moving one) gives way.
        std::set<int> involved;
        for (const Crossing& c : report.crossings)
            for (int i = 0; i < int(slot_patches.size()); ++i)
                if (slot_patches[i].count(c.patch_a) || slot_patches[i].count(c.patch_b))
                    involved.insert(i);
        if (involved.empty())
            for (int i = 0; i < int(state.slots.size()); ++i)
                involved.insert(i);
        int loser = *involved.begin();
        for (int i : involved)
            loser = loser_of(p, state, loser, i);
        std::string verdict = !report.intersection_free ? "patches cross in the simulator"
                              : !report.foldable        ? "the card does not fold"
                              : !report.stable          ? "a part moves freely"
                                                        : "a part is not enclosed when closed";
        out.warn(DiagnosticCode::mechanism_dropped,
                 "chain " + chain_names(p, state.slots[loser]) + ": " + verdict +
                     " with its mechanism; it is made stationary");
        demote(p, state, loser, "the full simulator's check failed (" + verdict + ")", reasons);
    }
    out.value = validity_s;
    return out;
}

} // namespace popup::motion
