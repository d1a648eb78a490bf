#include "build_mechanisms.hpp"

#include <algorithm>
#include <map>
#include <sstream>
#include <string>
#include <utility>

#include "bulk_stack.hpp"
#include "design_distance.hpp"
#include "popup/fitting/bulk_prism.hpp"
#include "popup/fitting/prism_ransac.hpp"

namespace popup {
namespace {

/// The bulk's stack replaces the one box when it lies a tenth closer to the samples or more.
constexpr double kStackGain = 0.9;

/// A fit of the bulk's boxes alone: the first on the card's hinge, the next (if any) on its top.
RansacResult bulk_design(const PrismHost& card, const std::vector<Prism>& boxes,
                         const SurfaceSamples& samples, long draws)
{
    RansacResult fit;
    fit.hosts = {card};
    fit.prisms = boxes;
    if (boxes.size() > 1)
        offer_box_pairs(boxes.front(), 0, fit.hosts);
    fit.owner.assign(samples.points.size(), -1);
    fit.on_base.assign(samples.points.size(), false);
    fit.on_principal.assign(samples.points.size(), false);
    fit.draws = draws;
    return fit;
}

} // namespace

BuiltMechanisms build_mechanisms(RansacResult fit, const SurfaceSamples& samples,
                                 const FitOptions& options, const CancelFlag* cancel,
                                 StageTimer& timer, FitResult& r)
{
    std::vector<MechanismPlan> plans;
    int plans_made = 0;
    auto plan_and_build = [&](const RansacResult& prisms) {
        Mapping mapping = map_mechanisms(prisms, samples);
        for (int k : mapping.unmapped) {
            const std::string name = "primitive " + std::to_string(k + 1);
            r.repairs.push_back({name, "dropped", "no mechanism of Table 5.1 fits its host"});
        }
        plans = mapping.plans;
        for (const auto& [name, why] : refit_for_foldability(plans, options.min_part_mm))
            r.repairs.push_back({name, "trimmed", why});
        // Strictly inside the generators' ranges, by a millionth of the card (docs/DESIGN.md).
        keep_inside_ranges(plans, options.card.width, options.card.depth,
                           1e-6 * std::max(options.card.width, options.card.depth));
        if (plans_made++ == 0) // the bulk box's mapping counts as validation time
            timer.lap("map");
        stop_if_cancelled(cancel, "fit_design: mapping");
        RepairOutcome outcome = build_until_valid(r.card, plans, options.min_part_mm, cancel);
        plans = outcome.plans;
        for (const FitRepair& repair : outcome.repairs)
            r.repairs.push_back(repair);
        for (const Diagnostic& d : outcome.warnings)
            r.diagnostics.push_back(d);
        return outcome;
    };
    const size_t repairs_before = r.repairs.size(), warnings_before = r.diagnostics.size();
    RepairOutcome outcome = plan_and_build(fit);
    // The model's bulk as one box fold (bulk_prism.hpp) when it stands up from the page (the
    // samples lie half as far from it as from the page alone): instead of nothing when nothing
    // the search found survives (a round model has no face a prism rests on), and instead of a
    // valid design the samples lie twice as far from on average (docs/DESIGN.md).
    const BulkBox bulk = bulk_box(samples, fit.hosts.front(), options.min_part_mm);
    std::string why;
    if (bulk.mean_distance <= 0.5 * bulk.page_distance) {
        if (!outcome.valid) {
            why = fit.prisms.empty() ? "no primitive was found on the model's surface"
                                     : "no fitted primitive gave a valid design";
        } else {
            const double fitted = mean_distance_to(outcome.scaffold, samples);
            if (bulk.mean_distance < 0.5 * fitted) {
                std::ostringstream m;
                m.precision(3);
                m << "the model lies " << fitted << " mm from the fitted design on average, "
                  << bulk.mean_distance << " mm from the box of its bulk";
                why = m.str();
            }
        }
    }
    if (!why.empty()) {
        // The first design's repairs were of mechanisms that are gone: only the reason stays.
        r.repairs.resize(repairs_before);
        r.diagnostics.resize(warnings_before);
        const size_t found = fit.prisms.size();
        const long draws = fit.draws;
        r.repairs.push_back({"primitives", "replaced",
                             std::to_string(found) + " fitted; " + why +
                                 ": the model's bulk is one box fold instead"});
        // A box and a box or a tent on its top, when they lie a tenth closer to the model than
        // one box (docs/MATH.md, "The model's bulk") and make a valid design; else the one box.
        const std::optional<BulkStack> stack =
            bulk_stack(samples, fit.hosts.front(), options.min_part_mm, bulk);
        if (stack && stack->mean_distance < kStackGain * bulk.mean_distance) {
            fit = bulk_design(fit.hosts.front(), {stack->lower, stack->upper}, samples, draws);
            outcome = plan_and_build(fit);
            if (outcome.valid &&
                std::all_of(outcome.kept.begin(), outcome.kept.end(), [](bool k) { return k; })) {
                const bool roof = stack->upper.kind == Prism::Kind::triangular;
                r.repairs[repairs_before].reason =
                    std::to_string(found) + " fitted; " + why + ": the model's bulk is " +
                    (roof ? "a box fold and a tent on its top" : "two box folds") +
                    " instead, one on the other's top";
                return {std::move(fit), std::move(plans), std::move(outcome)};
            }
            r.repairs.resize(repairs_before + 1);
            r.diagnostics.resize(warnings_before);
        }
        fit = bulk_design(fit.hosts.front(), {bulk.prism}, samples, draws);
        outcome = plan_and_build(fit);
    }
    return {std::move(fit), std::move(plans), std::move(outcome)};
}

void record_mechanisms(const BuiltMechanisms& built, FitResult& r)
{
    const std::vector<MechanismPlan>& plans = built.plans;
    const RepairOutcome& outcome = built.outcome;
    const RansacResult& fit = built.fit;
    r.scaffold = outcome.scaffold;
    r.valid = outcome.valid;
    std::vector<MechanismPlan> kept;
    for (size_t i = 0; i < plans.size(); ++i)
        if (outcome.kept[i])
            kept.push_back(plans[i]);
    for (const auto& p : kept) {
        FittedMechanism m;
        static_cast<DesignedMechanism&>(m) = p;
        m.primitive =
            std::string(fit.prisms[p.prism].kind_name()) + " prism " + std::to_string(p.prism + 1);
        m.coverage_error = p.coverage_error();
        r.mechanisms.push_back(m);
    }
    r.coverage_error = coverage_error(kept);
}

std::vector<FittedPrimitive> preview_primitives(const RansacResult& fit,
                                                const std::vector<MechanismPlan>& plans)
{
    std::vector<FittedPrimitive> primitives;
    std::map<int, std::string> host_names;
    for (const auto& p : plans)
        host_names[p.prism] = p.host;
    for (size_t k = 0; k < fit.prisms.size(); ++k) {
        const Prism& m = fit.prisms[k];
        FittedPrimitive fp;
        fp.kind = m.kind_name();
        fp.corners = m.corners(fit.hosts[m.host]);
        fp.host = host_names.count(int(k)) ? host_names[int(k)] : fit.hosts[m.host].name;
        fp.inliers = m.inliers;
        primitives.push_back(fp);
    }
    return primitives;
}

} // namespace popup
