#include "popup/fitting/fit_design.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "build_mechanisms.hpp"
#include "design_distance.hpp"
#include "design_profiles.hpp"
#include "outer_surface.hpp"
#include "popup/fitting/alignment.hpp"
#include "popup/fitting/surface_samples.hpp"
#include "primitive_search.hpp"
#include "stage_timer.hpp"

namespace popup {
namespace {

// The volume's grid: 128 cells along the model's longest side, closed over gaps up to 8 cells
// (6 % of that side: a house's windows and door, the cracks between an assembly's parts).
constexpr int kVolumeCells = 128;
constexpr int kVolumeClosing = 4;

} // namespace

Result<FitResult> fit_design(const ModelMesh& given, const FitOptions& options,
                             const CancelFlag* cancel)
{
    Result<FitResult> result;
    Diagnostics bad = check_fit_options(options);
    if (!bad.empty()) {
        result.fail_with(bad);
        return result;
    }
    const Result<ModelMesh> checked = check_model(given);
    if (!checked.ok) {
        result.fail_with(checked.diagnostics);
        return result;
    }
    stop_if_cancelled(cancel, "fit_design");
    FitResult& r = result.value;
    StageTimer timer(r);

    // Alignment (§5.1.1): the up the model stands on, the mirror plane, the bounding box and
    // the scale; a model with no mirror plane offers a few alignments, each fitted below.
    // The volume the surface encloses, closed over windows and seams (docs/MATH.md, "The
    // model's volume"): faces turned to face out of it, samples inside it flagged.
    const OccupancyGrid volume(given, kVolumeCells, kVolumeClosing);
    int turned = 0;
    const ModelMesh model = faces_turned_out(given, volume, turned);
    const SurfaceSamples coarse = outer_only(outer_surface(
        volume, sample_surface(model, std::min(options.samples, 4000), options.seed)));
    CardRoom room{options.card, options.margin};
    const Result<std::vector<Alignment>> aligned =
        alignment_candidates(model, coarse, options.up, options.facing, room);
    if (!aligned.ok) {
        result.fail_with(aligned.diagnostics);
        return result;
    }
    r.card = options.card;
    timer.lap("align");
    stop_if_cancelled(cancel, "fit_design: alignment");

    // Pseudo-vertices in model units, placed on the card per alignment.
    // A plate under the model is the page: its samples are the card's, not the pop-up's.
    r.plate = aligned.value.front().plate;
    const ModelMesh standing = r.plate ? above_plate(model, *r.plate) : ModelMesh();
    const ModelMesh& shown = r.plate ? standing : model;
    SurfaceSamples spread = sample_surface(shown, options.samples, options.seed + 1);
    if (r.plate) // the plate's top face under what stands on it
        spread = samples_above(*r.plate, spread);
    const OuterSurface outer = outer_surface(volume, spread);
    r.inner_samples = outer.inner_count;
    r.turned_faces = turned;
    r.outer_samples = int(spread.points.size()) - outer.inner_count;
    const SurfaceSamples& model_samples = outer.samples;
    timer.lap("sample");
    stop_if_cancelled(cancel, "fit_design: sampling");

    // Volumetric RANSAC on the base patch pairs, from the central fold, under every alignment.
    const PrimitiveSearch best =
        search_primitives(model, model_samples, outer.inner, aligned.value, options, cancel);
    const Alignment& a = aligned.value[best.alignment];
    r.model_to_card = a.model_to_card;
    r.symmetry_error = a.symmetry_error;
    const SurfaceSamples& samples = best.samples;
    const RansacOptions& ro = best.ro;
    r.ransac_draws = best.fit.draws;
    timer.lap("fit_primitives");
    stop_if_cancelled(cancel, "fit_design: fitting primitives");

    // Table 5.1 mapping, the §4.2.2 refit, validity; or the model's bulk as one box fold.
    const BuiltMechanisms built = build_mechanisms(best.fit, samples, options, cancel, timer, r);
    const ValidityReport& report = built.outcome.report;
    timer.lap("validate");
    record_mechanisms(built, r);
    // §5.1.3: principal patches take the model's outline, as long as the design stays valid.
    if (options.outlines && r.valid) {
        if (const auto refused =
                profile_design(shown, options, built.outcome.pairs, cancel, timer, r)) {
            result.fail_with(*refused);
            return result;
        }
    }
    r.primitives = preview_primitives(built.fit, built.plans);
    r.coverage = coverage_of(r.scaffold, samples, ro.threshold);
    for (const Diagnostic& d : r.diagnostics)
        result.diagnostics.push_back(d);
    if (!r.valid) {
        for (const Diagnostic& d : report.diagnostics)
            r.diagnostics.push_back(d);
        result.fail(DiagnosticCode::no_design_found,
                    (model.source.empty() ? std::string("the model") : model.source) +
                        ": no valid design found (" + std::to_string(built.fit.prisms.size()) +
                        " primitives fitted, " + std::to_string(built.plans.size()) +
                        " mapped, every one dropped; see the repairs)");
    }
    timer.lap("report");
    timer.finish();
    return result;
}

} // namespace popup
