#include "popup/fitting/fit_design.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>
#include <sstream>
#include <utility>

#include "popup/fitting/alignment.hpp"
#include "popup/fitting/bulk_prism.hpp"
#include "popup/fitting/design_repair.hpp"
#include "popup/fitting/fit_depth_layers.hpp"
#include "popup/fitting/fit_outlines.hpp"
#include "popup/fitting/mechanism_mapping.hpp"
#include "popup/fitting/prism_ransac.hpp"
#include "popup/fitting/surface_samples.hpp"
#include "popup/simulation/check_validity.hpp"

namespace popup {
namespace {

using Clock = std::chrono::steady_clock;

class StageTimer {
public:
    explicit StageTimer(FitResult& r) : r_(r), start_(Clock::now()) {}
    void lap(const std::string& stage)
    {
        const auto now = Clock::now();
        r_.timings_s.push_back({stage, std::chrono::duration<double>(now - start_).count()});
        start_ = now;
    }

private:
    FitResult& r_;
    Clock::time_point start_;
};

void range(Diagnostics& out, const std::string& option, double value, bool ok,
           const std::string& allowed)
{
    if (ok)
        return;
    std::ostringstream m;
    m << "FitOptions." << option << " = " << value << ", must be " << allowed;
    out.push_back(Diagnostic::error(DiagnosticCode::bad_option, m.str(), about_parameter(option)));
}

/// Distance from x to a planar patch (its outline, holes ignored: a patch covers its face).
double distance_to_patch(const Patch& patch, const std::vector<Vec2>& outline, const Vec3& x)
{
    const double off = (x - patch.origin).dot(patch.normal);
    const Vec2 q = patch.to_local(x);
    bool inside = false;
    double edge = 1e300;
    for (size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
        const Vec2 &a = outline[j], &b = outline[i];
        if ((a.y() > q.y()) != (b.y() > q.y()) &&
            q.x() < a.x() + (q.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
            inside = !inside;
        const Vec2 d = b - a;
        const double t = std::clamp((q - a).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
        edge = std::min(edge, (a + t * d - q).norm());
    }
    return inside ? std::abs(off) : std::hypot(off, edge);
}

/// The scaffold's patches with their frames derived, and each outline in its patch's frame.
std::pair<std::vector<Patch>, std::vector<std::vector<Vec2>>>
framed_outlines(const Scaffold& scaffold)
{
    std::vector<Patch> patches = scaffold.patches;
    std::vector<std::vector<Vec2>> outlines;
    for (Patch& p : patches) {
        p.derive_frame();
        std::vector<Vec2> o;
        for (const Vec3& v : p.outer)
            o.push_back(p.to_local(v));
        outlines.push_back(o);
    }
    return {patches, outlines};
}

double coverage_of(const Scaffold& scaffold, const SurfaceSamples& samples, double eps)
{
    const auto [patches, outlines] = framed_outlines(scaffold);
    size_t near = 0;
    for (const Vec3& x : samples.points)
        for (size_t k = 0; k < patches.size(); ++k)
            if (distance_to_patch(patches[k], outlines[k], x) <= eps) {
                ++near;
                break;
            }
    return samples.points.empty() ? 0.0 : double(near) / double(samples.points.size());
}

/// Mean distance from (at most 3000 of) the samples to the scaffold's patches.
double mean_distance_to(const Scaffold& scaffold, const SurfaceSamples& samples)
{
    const auto [patches, outlines] = framed_outlines(scaffold);
    const size_t step = std::max<size_t>(1, samples.points.size() / 3000);
    double sum = 0;
    size_t n = 0;
    for (size_t i = 0; i < samples.points.size(); i += step, ++n) {
        double nearest = 1e300;
        for (size_t k = 0; k < patches.size(); ++k)
            nearest =
                std::min(nearest, distance_to_patch(patches[k], outlines[k], samples.points[i]));
        sum += nearest;
    }
    return n ? sum / double(n) : 0.0;
}

} // namespace

Diagnostics check_fit_options(const FitOptions& o)
{
    Diagnostics d;
    range(d, "card_width", o.card_width, o.card_width >= 20 && o.card_width <= 2000,
          ">= 20 and <= 2000 mm");
    range(d, "card_depth", o.card_depth, o.card_depth >= 20 && o.card_depth <= 2000,
          ">= 20 and <= 2000 mm");
    range(d, "margin", o.margin, o.margin >= 0 && o.margin < 0.4, ">= 0 and < 0.4");
    range(d, "max_mechanisms", o.max_mechanisms, o.max_mechanisms >= 1 && o.max_mechanisms <= 32,
          "1 to 32");
    range(d, "min_shape", o.min_shape, o.min_shape > 0 && o.min_shape < 1,
          "> 0 and < 1 (a fraction of the model's diagonal)");
    range(d, "probability", o.probability, o.probability > 0 && o.probability < 1, "> 0 and < 1");
    range(d, "threshold", o.threshold, o.threshold > 0 && o.threshold <= 0.2,
          "> 0 and <= 0.2 (a fraction of the model's diagonal)");
    range(d, "min_part_mm", o.min_part_mm,
          o.min_part_mm >= 0 && o.min_part_mm <= 0.25 * std::min(o.card_width, o.card_depth),
          ">= 0 and <= a quarter of the card's smaller dimension (mm)");
    range(d, "samples", o.samples, o.samples >= 500 && o.samples <= 2000000, "500 to 2000000");
    return d;
}

Result<FitResult> fit_design(const ModelMesh& model, const FitOptions& options,
                             const CancelFlag* cancel)
{
    Result<FitResult> result;
    Diagnostics bad = check_fit_options(options);
    if (!bad.empty()) {
        result.fail_with(bad);
        return result;
    }
    const Result<ModelMesh> checked = check_model(model);
    if (!checked.ok) {
        result.fail_with(checked.diagnostics);
        return result;
    }
    stop_if_cancelled(cancel, "fit_design");
    FitResult& r = result.value;
    StageTimer timer(r);

    // Alignment (§5.1.1): the up the model stands on, the mirror plane, the bounding box and
    // the scale; a model with no mirror plane offers a few alignments, each fitted below.
    const SurfaceSamples coarse =
        sample_surface(model, std::min(options.samples, 4000), options.seed);
    CardRoom room{options.card_width, options.card_depth, options.margin};
    const Result<std::vector<Alignment>> aligned =
        alignment_candidates(model, coarse, options.up, options.facing, room);
    if (!aligned.ok) {
        result.fail_with(aligned.diagnostics);
        return result;
    }
    r.card.width = options.card_width;
    r.card.depth = options.card_depth;
    timer.lap("align");
    stop_if_cancelled(cancel, "fit_design: alignment");

    // Pseudo-vertices in model units, placed on the card per alignment.
    const SurfaceSamples model_samples = sample_surface(model, options.samples, options.seed + 1);
    timer.lap("sample");
    stop_if_cancelled(cancel, "fit_design: sampling");

    // Volumetric RANSAC on the base patch pairs, from the central fold.
    struct Attempt {
        SurfaceSamples samples;
        RansacOptions ro;
        RansacResult fit;
        double explained = 0; ///< samples on a prism's paper faces or on a host's page
    };
    auto attempt = [&](const Alignment& a) {
        Attempt t;
        t.samples = transformed(model_samples, a.model_to_card);
        const double diagonal = a.scale * model.diagonal();
        PrismHost card;
        card.name = "central fold";
        card.origin = Vec3::Zero();
        card.length = options.card_width;
        card.across_min = -options.card_depth;
        card.across_max = options.card_depth;
        RansacOptions& ro = t.ro;
        ro.threshold = options.threshold * diagonal;
        // τ in samples: the five visible faces of a cube of edge min_shape·diagonal.
        const double tau = options.min_shape * diagonal;
        ro.min_points =
            std::max(8.0, 5 * tau * tau / std::max(t.samples.spacing * t.samples.spacing, 1e-300));
        ro.probability = options.probability;
        ro.seed = options.seed;
        ro.max_primitives = options.max_mechanisms;
        ro.min_part = options.min_part_mm;
        ro.cancel = cancel;
        t.fit = fit_prisms(t.samples, card, ro);
        size_t n = 0;
        for (size_t i = 0; i < t.fit.owner.size(); ++i)
            n += t.fit.on_principal[i] || t.fit.on_base[i];
        t.explained = t.fit.owner.empty() ? 0.0 : double(n) / double(t.fit.owner.size());
        return t;
    };
    // The alignment whose primitives' paper faces (not their open ends) explain the most
    // samples; the first (the mirror plane)
    // unless another explains a hundredth more (docs/MATH.md, "Which way is up").
    size_t chosen = 0;
    Attempt best = attempt(aligned.value.front());
    for (size_t k = 1; k < aligned.value.size(); ++k) {
        Attempt t = attempt(aligned.value[k]);
        if (t.explained > best.explained + 0.01) {
            best = std::move(t);
            chosen = k;
        }
    }
    const Alignment& a = aligned.value[chosen];
    r.model_to_card = a.model_to_card;
    r.symmetry_error = a.symmetry_error;
    const SurfaceSamples& samples = best.samples;
    const RansacOptions& ro = best.ro;
    RansacResult fit = best.fit;
    r.ransac_draws = fit.draws;
    timer.lap("fit_primitives");
    stop_if_cancelled(cancel, "fit_design: fitting primitives");

    // Table 5.1 mapping by coverage error, the §4.2.2 refit, then validity: build, check
    // everything, drop what the simulator refuses, check again.
    std::vector<MechanismPlan> plans;
    int plans_made = 0;
    auto plan_and_build = [&](const RansacResult& prisms) {
        Mapping mapping = map_mechanisms(prisms);
        for (int k : mapping.unmapped) {
            const std::string name = "primitive " + std::to_string(k + 1);
            r.repairs.push_back({name, "dropped", "no mechanism of Table 5.1 fits its host"});
        }
        plans = mapping.plans;
        for (const auto& [name, why] : refit_for_foldability(plans, options.min_part_mm))
            r.repairs.push_back({name, "trimmed", why});
        // Strictly inside the generators' ranges, by a millionth of the card (docs/DESIGN.md).
        keep_inside_ranges(plans, options.card_width, options.card_depth,
                           1e-6 * std::max(options.card_width, options.card_depth));
        if (plans_made++ == 0) // the bulk box's mapping counts as validation time
            timer.lap("map");
        stop_if_cancelled(cancel, "fit_design: mapping");
        RepairOutcome outcome = build_until_valid(r.card, plans, cancel);
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
        RansacResult replaced;
        replaced.hosts = {fit.hosts.front()};
        replaced.prisms = {bulk.prism};
        replaced.owner.assign(samples.points.size(), -1);
        replaced.on_base.assign(samples.points.size(), false);
        replaced.on_principal.assign(samples.points.size(), false);
        replaced.draws = fit.draws;
        const size_t found = fit.prisms.size();
        fit = std::move(replaced);
        r.repairs.push_back({"primitives", "replaced",
                             std::to_string(found) + " fitted; " + why +
                                 ": the model's bulk is one box fold instead"});
        outcome = plan_and_build(fit);
    }
    const ValidityReport& report = outcome.report;
    timer.lap("validate");

    r.scaffold = outcome.scaffold;
    r.valid = outcome.valid;
    std::vector<MechanismPlan> kept;
    for (size_t i = 0; i < plans.size(); ++i)
        if (outcome.kept[i])
            kept.push_back(plans[i]);
    for (const auto& p : kept) {
        FittedMechanism m;
        m.type = p.type;
        m.name = p.name;
        m.host = p.host;
        m.parameters = p.parameters;
        m.primitive =
            std::string(fit.prisms[p.prism].kind_name()) + " prism " + std::to_string(p.prism + 1);
        m.coverage_error = p.coverage_error();
        r.mechanisms.push_back(m);
    }
    r.coverage_error = coverage_error(kept);
    // §5.1.3: principal patches take the model's outline, as long as the design stays valid.
    if (options.outlines && r.valid) {
        OutlineOutcome outlined = fit_outlines_for(model, r.model_to_card, r.scaffold, r.mechanisms,
                                                   cancel, options.min_part_mm);
        r.scaffold = std::move(outlined.scaffold);
        r.profiles = std::move(outlined.profiles);
        for (const FitRepair& repair : outlined.dropped)
            r.repairs.push_back(repair);
        timer.lap("outlines");
        // §5.1.3: box fronts and tops in depth layers, each kept only when it helps.
        if (options.depth_layers) {
            DepthLayerFitOptions lo;
            lo.min_part_mm = options.min_part_mm;
            lo.seed = options.seed;
            lo.range_margin = 1e-6 * std::max(options.card_width, options.card_depth);
            Result<DepthLayerOutcome> tried = fit_depth_layers(
                model, r.model_to_card, r.scaffold, r.mechanisms, outcome.pairs, lo, cancel);
            if (!tried.ok) { // its options come from checked FitOptions: not expected
                result.fail_with(tried.diagnostics);
                return result;
            }
            for (const Diagnostic& d : tried.diagnostics)
                r.diagnostics.push_back(d);
            DepthLayerOutcome& layered = tried.value;
            r.scaffold = std::move(layered.scaffold);
            for (FittedMechanism& m : layered.mechanisms)
                r.mechanisms.push_back(std::move(m));
            for (FittedProfile& p : layered.profiles)
                r.profiles.push_back(std::move(p));
            for (FitRepair& repair : layered.repairs)
                r.repairs.push_back(std::move(repair));
            r.depth_layers = std::move(layered.layers);
            timer.lap("depth_layers");
        }
    }
    // Primitives for previews, named by the pairs their mechanisms offer where mapped.
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
        r.primitives.push_back(fp);
    }
    r.coverage = coverage_of(r.scaffold, samples, ro.threshold);
    for (const Diagnostic& d : r.diagnostics)
        result.diagnostics.push_back(d);
    if (!r.valid) {
        for (const Diagnostic& d : report.diagnostics)
            r.diagnostics.push_back(d);
        result.fail(DiagnosticCode::no_design_found,
                    (model.source.empty() ? std::string("the model") : model.source) +
                        ": no valid design found (" + std::to_string(fit.prisms.size()) +
                        " primitives fitted, " + std::to_string(plans.size()) +
                        " mapped, every one dropped; see the repairs)");
    }
    timer.lap("report");
    return result;
}

} // namespace popup
